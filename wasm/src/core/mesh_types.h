// Types shared by the whole C++ core. Plain C++ and CGAL: no Emscripten here.
#pragma once

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace subdivlab {

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

/// How the border of a mesh is subdivided when it carries tags, as
/// OpenSubdiv's Sdc::Options::VtxBoundaryInterpolation (and the OBJ tag
/// `t interpolateboundary 1/0/0 N`: 0 none, 1 edge and corner, 2 edge only).
enum class Boundary_interpolation : std::uint8_t {
  /// Border edges sharp (CGAL's border rules; the default).
  edge_only = 0,
  /// Also every vertex of a single face with two border edges a corner.
  edge_and_corner = 1,
  /// Faces at the border are holes: they shape their neighbours only.
  none = 2,
};

/// How semi-sharp sharpness decays from level to level, as OpenSubdiv's
/// Sdc::Options::CreasingMethod (OBJ tag `t creasemethod 0/0/1 normal` or
/// `chaikin`).
enum class Crease_method : std::uint8_t {
  uniform = 0,  ///< every sharpness less one per level (the default)
  chaikin = 1,  ///< a crease's edges blend their sharpness along it
};

/// OpenSubdiv's tags on a mesh (OBJ `t` lines: crease, corner, hole,
/// interpolateboundary, creasemethod; in OFF the same lines as `# t ...`
/// comments after the faces), which Catmull-Clark and Loop apply with
/// OpenSubdiv's rules. Sharpness is OpenSubdiv's float: 0 smooth, 10 and
/// above infinitely sharp, decreasing by one per level in between. The
/// reader keeps the order of first appearance (a repeated edge or vertex
/// keeps its first place and its last value), so that load-save-load gives
/// the same tags.
struct Mesh_tags {
  /// Pairs of vertex indices a0 b0 a1 b1 ..., each an edge of the mesh,
  /// with the sharpness of each pair (> 0; an edge appears once, in the
  /// direction the file first gave it).
  std::vector<std::uint32_t> crease_edges;
  std::vector<float> crease_sharpness;
  /// Vertex indices with their sharpness (> 0; a vertex appears once).
  std::vector<std::uint32_t> corner_vertices;
  std::vector<float> corner_sharpness;
  /// Face indices (ascending, once each) that are holes: still part of the
  /// mesh, refined and shaping their neighbours, but not drawn.
  std::vector<std::uint32_t> holes;
  Boundary_interpolation boundary = Boundary_interpolation::edge_only;
  /// The file had an interpolateboundary tag (written back on export).
  bool boundary_given = false;
  Crease_method crease_method = Crease_method::uniform;
  /// The file had a creasemethod tag (written back on export).
  bool crease_method_given = false;
  /// One line per well-formed tag the product does not apply
  /// ("line 12: tag 'smoothtriangles' is not applied"; after 100 of them
  /// one line counts the rest) or corner it dropped with its unused vertex,
  /// for the user; never written back and no part of a result.
  std::vector<std::string> notes;

  /// Nothing that changes a result: no crease, corner or hole, and the
  /// default border rules.
  bool empty() const {
    return crease_edges.empty() && corner_vertices.empty() && holes.empty() &&
           boundary == Boundary_interpolation::edge_only;
  }

  /// Anything at all to show or write: a tag that changes a result, an
  /// interpolateboundary or creasemethod tag (even one that gives the
  /// default), a non-default crease method, or a note.
  bool present() const {
    return !empty() || boundary_given || crease_method_given ||
           crease_method != Crease_method::uniform || !notes.empty();
  }
};

/// The interchange form of a polygon mesh: flat arrays, polygons kept as
/// polygons. Face f uses face_indices[o .. o + face_sizes[f]) where o is the
/// sum of the earlier face sizes.
struct Mesh_buffers {
  std::vector<double> positions;            ///< x0 y0 z0 x1 y1 z1 ...
  std::vector<std::uint32_t> face_sizes;    ///< degree of each face
  std::vector<std::uint32_t> face_indices;  ///< vertex indices, face by face
  /// Edges of the level-0 (control) mesh that survive in this mesh, as pairs
  /// of vertex indices a0 b0 a1 b1 ...; empty when not tracked.
  std::vector<std::uint32_t> control_edges;
  /// OpenSubdiv's tags (creases, corners, holes, border mode); empty on
  /// meshes without them.
  Mesh_tags tags;

  std::size_t vertex_count() const { return positions.size() / 3; }
  std::size_t face_count() const { return face_sizes.size(); }
  /// The degree every face has, or 0 when they differ (or there are none).
  std::uint32_t uniform_face_degree() const {
    if (face_sizes.empty()) return 0;
    const std::uint32_t k = face_sizes[0];
    for (std::uint32_t size : face_sizes)
      if (size != k) return 0;
    return k;
  }
};

/// What went wrong, as data. The bindings turn it into a JS error.
enum class Status_code {
  ok = 0,
  parse_error,   ///< the file is not a valid OFF/OBJ/PLY/STL file
  invalid_mesh,  ///< parsed, but not a valid oriented 2-manifold polygon mesh
  /// invalid_mesh whose first problem is faces turned inconsistently on an
  /// orientable surface: reading again with Read_options::repair_orientation
  /// turns them to agree.
  inconsistent_orientation,
  not_triangles,  ///< a scheme needs triangles and the mesh has other faces
  too_large,  ///< the result would not fit in memory (predicted, or ran out)
  invalid_argument,  ///< unknown scheme, negative levels, bad weights ...
  internal_error     ///< CGAL or the core threw where it should not have
};

struct Status {
  Status_code code = Status_code::ok;
  std::string message;  ///< full sentence naming the problem, without file name
  int line = 0;  ///< 1-based line in the input text, 0 when not applicable

  bool ok() const { return code == Status_code::ok; }
  static Status success() { return {}; }
  static Status error(Status_code c, std::string m, int l = 0) {
    return Status{c, std::move(m), l};
  }
};

/// A value or the reason there is none.
template <class T>
struct Result {
  Status status;
  T value{};
  bool ok() const { return status.ok(); }
};

/// Name of a status code as it crosses to JS ("parse_error", ...).
inline const char* status_code_name(Status_code c) {
  switch (c) {
    case Status_code::ok:
      return "ok";
    case Status_code::parse_error:
      return "parse_error";
    case Status_code::invalid_mesh:
      return "invalid_mesh";
    case Status_code::inconsistent_orientation:
      return "inconsistent_orientation";
    case Status_code::not_triangles:
      return "not_triangles";
    case Status_code::too_large:
      return "too_large";
    case Status_code::invalid_argument:
      return "invalid_argument";
    case Status_code::internal_error:
      return "internal_error";
  }
  return "internal_error";
}

}  // namespace subdivlab
