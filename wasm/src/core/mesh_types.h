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

  std::size_t vertex_count() const { return positions.size() / 3; }
  std::size_t face_count() const { return face_sizes.size(); }
};

/// What went wrong, as data. The bindings turn it into a JS error.
enum class Status_code {
  ok = 0,
  parse_error,    ///< the text is not a valid OFF/OBJ file
  invalid_mesh,   ///< parsed, but not a valid oriented 2-manifold polygon mesh
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
