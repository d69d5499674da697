// The subdivision schemes. Owner: subdivide.cpp (the dispatch and size
// predictions; its routes in fast_driver.cpp and cgal_driver.cpp, their
// shared checks in subdivide_prepare.cpp; + the host/mask headers).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "custom_rules.h"
#include "mesh_types.h"

namespace subdivlab {

struct Subdivide_options {
  /// "catmull-clark", "loop", "doo-sabin", "sqrt3" (issue 4 adds
  /// "quad-triangle", "linear", "linear-tri", "custom").
  std::string scheme = "catmull-clark";
  int levels = 1;  ///< 0 = no change (the mesh is still checked)
  /// Level of the input mesh in the caller's history. √3 refines the border
  /// only on odd steps; carrying the level makes k single steps equal one
  /// call of k levels.
  int start_level = 0;
  bool triangulate = false;  ///< triangulate first when the scheme needs it
  /// Memory the result may take; a step predicted to need more fails with
  /// Status_code::too_large before anything is allocated. 0 = default
  /// (3.5 GB under WebAssembly's 4 GB, unlimited natively).
  std::size_t memory_limit_bytes = 0;
  /// quad-triangle: border vertices follow the cubic B-spline border rule
  /// (true) or stay on the control border polygon (false).
  bool smooth_boundary = true;
  /// custom: the host and the mask weights (custom_rules.h).
  Custom_rules custom;
  /// Catmull-Clark and Loop on a mesh with tags (Mesh_tags): override the
  /// mesh's creasemethod and interpolateboundary tags when set.
  std::optional<Crease_method> crease_method;
  std::optional<Boundary_interpolation> boundary;
  /// Run CGAL's hosts even where a fast host (refine/) exists: the
  /// reference the fast hosts are compared with, in the tests and in the
  /// benchmark's CGAL column. Same results (to 1e-12), more time and memory.
  bool cgal_hosts = false;
  /// The caller builds the result's render arrays while the result and the
  /// input are alive (level_view.h): the last step's memory check and
  /// prediction include them.
  bool render_buffers = false;
};

/// Counts predicted for a mesh after `levels` steps of a scheme, and the
/// peak bytes of the run: the largest of its steps, in practice the last
/// (CGAL's hosts reserve more than they keep).
/// 64-bit even under wasm32, whose size_t would saturate a run beyond 4 G
/// elements or bytes at 4294967295.
struct Size_prediction {
  std::uint64_t vertices = 0, edges = 0, faces = 0;
  std::uint64_t peak_bytes = 0;
};

/// Predicts counts without subdividing. Fails for unknown schemes.
Result<Size_prediction> predict_size(const Mesh_buffers& mesh,
                                     const Subdivide_options& options);

/// What predict_size needs of a closed mesh without tags, known only by its
/// counts (a level the app keeps, with its facts).
struct Closed_mesh_counts {
  std::uint64_t vertices = 0, edges = 0, faces = 0;
  std::uint64_t triangles = 0;      ///< faces of degree 3
  std::uint64_t control_edges = 0;  ///< marked edges given with the mesh
};

/// predict_size of a closed mesh without tags from its counts, without its
/// arrays: the same figures, for a mesh that a step with the same options
/// made (so that the checks of its run passed). Fails as predict_size does
/// (options, triangles); with `triangulate` on a mesh that needs it, which
/// needs the faces, it fails with invalid_argument: ask predict_size.
Result<Size_prediction> predict_size(const Closed_mesh_counts& mesh,
                                     const Subdivide_options& options);

/// Subdivides `mesh` `options.levels` times. Preconditions checked first:
/// a valid mesh (build_mesh), a known scheme, levels >= 0, triangles for
/// loop and sqrt3 unless options.triangulate, and the predicted size under
/// the memory limit. Never throws: CGAL failures become internal_error.
Result<Mesh_buffers> subdivide_mesh(const Mesh_buffers& mesh,
                                    const Subdivide_options& options);

/// Scheme names known to subdivide_mesh, in display order.
std::vector<std::string> scheme_names();

/// A refinement host: how a step changes the connectivity. The schemes'
/// needs and the size model are keyed by host, so that a custom rule set
/// on a host behaves as the built-in scheme on it.
struct Host_info {
  std::string name;          ///< "pqq", "ptq", "dqq", "sqrt3", "pqt"
  bool needs_triangles;      ///< refuses other faces (not_triangles)
  bool keeps_control_edges;  ///< primal: old vertices kept first, every
                             ///< edge split at one new vertex
  bool fast;                 ///< runs on the fast hosts (refine/)
  std::string size_model;    ///< the scheme whose counts a step follows
  std::string label;         ///< "PQQ", "PTQ", "DQQ", "√3", "PQT"
};

/// A scheme: a host and the weights of its mask.
struct Scheme_info {
  std::string name;
  std::string label;        ///< the name a picker shows
  std::string host;         ///< a Host_info name; empty for custom (its rules')
  std::string description;  ///< one line for a picker
  /// Applies OpenSubdiv's tags (creases, corners, holes, border modes;
  /// refine/crease.h): the schemes OpenSubdiv has, on the fast hosts.
  bool creases = false;
};

/// The hosts, and the schemes in display order.
const std::vector<Host_info>& host_table();
const std::vector<Scheme_info>& scheme_table();

}  // namespace subdivlab
