// Every scheme at levels 1 and 2 on what the readers accept (the format
// told from the bytes as the app's "auto" does), the options from the last
// byte (triangulate, smooth_boundary, crease method and border overrides,
// an odd start level). Inputs over a size cap (kMaxFaces, kMaxCorners) are
// skipped: two levels of a bigger mesh only make an execution slower. What
// the headers promise:
//   - no internal_error (nor too_large: no memory limit natively, tiny
//     results), only the refusals a scheme documents;
//   - a result is a valid mesh with finite coordinates, with the counts
//     predict_size gave, its control edges edges of it;
//   - one call of two levels has the counts of two calls of one
//     (start_level carried; meshes without tags, whose results carry none
//     to the next call; a second call numbers the vertices from its own
//     Surface_mesh, so not the same indices);
//   - the fast hosts equal CGAL's hosts (cgal_hosts): same faces, points
//     to 1e-9 of the result's size, same control edges (untagged meshes
//     and the default border rules: CGAL's hosts do not crease), unless
//     CGAL's overflow near the largest double where the fast hosts do not.

#include <fuzzer/FuzzedDataProvider.h>

#include "core/subdivide.h"
#include "fuzz_targets.h"

namespace subdivlab::fuzz {
namespace {

constexpr std::size_t kMaxFaces = 40;
constexpr std::size_t kMaxCorners = 160;

}  // namespace

void fuzz_schemes(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider bytes(data, size);
  const std::uint8_t flags = bytes.ConsumeIntegral<std::uint8_t>();
  const std::string text = bytes.ConsumeRemainingBytesAsString();
  Mesh_buffers mesh;
  if (!read_any(text, mesh)) return;
  if (mesh.face_count() > kMaxFaces || mesh.face_indices.size() > kMaxCorners)
    return;
  for (const std::string& scheme : scheme_names()) {
    if (scheme == "custom") continue;  // fuzz_rules
    Subdivide_options o;
    o.scheme = scheme;
    o.levels = 2;
    o.triangulate = flags & 1;
    o.smooth_boundary = !(flags & 2);
    if ((flags >> 2) & 3)
      o.crease_method = ((flags >> 2) & 3) == 1 ? Crease_method::uniform
                                                : Crease_method::chaikin;
    if ((flags >> 4) & 3)
      o.boundary = static_cast<Boundary_interpolation>(((flags >> 4) & 3) - 1);
    o.start_level = (flags >> 6) & 1;
    const std::string what = scheme + " flags " + std::to_string(flags);

    const Result<Mesh_buffers> two = subdivide_mesh(mesh, o);
    require_sane_status(two.status, "subdivide_mesh");
    require(two.status.code != Status_code::too_large,
            "too_large on a tiny mesh", what + ": " + two.status.message);
    Subdivide_options one_level = o;
    one_level.levels = 1;
    const Result<Mesh_buffers> one = subdivide_mesh(mesh, one_level);
    require_sane_status(one.status, "subdivide_mesh");
    if (!two.ok()) {
      // A refusal of the mesh or the options (not_triangles, tags that do
      // not fit) comes before level 1, and level 1 fails alike; an
      // overflow may come at level 2 only.
      if (two.status.message.find("overflows") == std::string::npos)
        require(!one.ok() && one.status.message == two.status.message,
                "two levels refused, one level not alike",
                what + ": " + two.status.message + " | " + one.status.message);
      continue;
    }
    require(one.ok(), "one level refused where two succeed",
            what + ": " + one.status.message);
    require_result(mesh, o, two.value, what + " level 2");
    require_result(mesh, one_level, one.value, what + " level 1");

    // CGAL's hosts do not crease: compare where nothing is creased (no
    // tags, and the border rules not overridden to sharpen corners).
    if (!mesh.tags.empty() ||
        (o.boundary && *o.boundary != Boundary_interpolation::edge_only))
      continue;
    Subdivide_options next = one_level;
    next.start_level = o.start_level + 1;
    const Result<Mesh_buffers> stepped = subdivide_mesh(one.value, next);
    require_sane_status(stepped.status, "subdivide_mesh");
    require(stepped.ok(), "the second single step refused",
            what + ": " + stepped.status.message);
    require(stepped.value.vertex_count() == two.value.vertex_count() &&
                stepped.value.face_count() == two.value.face_count() &&
                stepped.value.face_indices.size() ==
                    two.value.face_indices.size() &&
                stepped.value.control_edges.size() ==
                    two.value.control_edges.size(),
            "two levels differ from two single steps", what);

    Subdivide_options cgal = o;
    cgal.cgal_hosts = true;
    const Result<Mesh_buffers> reference = subdivide_mesh(mesh, cgal);
    require_sane_status(reference.status, "subdivide_mesh on CGAL's hosts");
    // Near the largest double, CGAL's masks can overflow where the fast
    // hosts' do not (its Doo-Sabin quad corner adds 9, 3, 3 and 1 times the
    // corners and divides by 16 last): the fast hosts are what the product
    // runs, CGAL's the reference for ordinary input.
    if (!reference.ok() &&
        reference.status.message.find("overflows") != std::string::npos)
      continue;
    require(reference.ok(), "CGAL's hosts refuse what the fast hosts take",
            what + ": " + reference.status.message);
    require(same_result(two.value, reference.value),
            "the fast hosts differ from CGAL's", what);
  }
}

}  // namespace subdivlab::fuzz
