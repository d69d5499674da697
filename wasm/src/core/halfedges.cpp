// Owner of halfedges.h.
#include "halfedges.h"

#include "mesh_build.h"

namespace subdivlab {

Result<Halfedge_table> halfedge_table(const Mesh_buffers& buffers) {
  Mesh mesh;
  const Status built = build_mesh(buffers, mesh);
  if (!built.ok()) return {built, {}};
  // A mesh fresh from build_mesh has no removed elements: its indices run
  // 0..n-1 and are the ones a user of CGAL sees.
  Halfedge_table t;
  const std::size_t n = mesh.number_of_halfedges();
  t.next.resize(n);
  t.prev.resize(n);
  t.opposite.resize(n);
  t.target.resize(n);
  t.face.resize(n);
  for (const Mesh::Halfedge_index h : mesh.halfedges()) {
    const std::size_t i = h.idx();
    t.next[i] = mesh.next(h).idx();
    t.prev[i] = mesh.prev(h).idx();
    t.opposite[i] = mesh.opposite(h).idx();
    t.target[i] = mesh.target(h).idx();
    const Mesh::Face_index f = mesh.face(h);
    t.face[i] =
        f == Mesh::null_face() ? -1 : static_cast<std::int32_t>(f.idx());
  }
  return {Status::success(), std::move(t)};
}

}  // namespace subdivlab
