// The readers: read_mesh on any bytes as OFF, OBJ, PLY or STL. Beyond
// crashes, leaks and UB, what the headers promise:
//   - the status is sane (fuzz_targets.h): never internal_error;
//   - the fast path and the general path agree (detail::read_mesh_general:
//     same buffers, tags, messages, lines and corner halfedges);
//   - an accepted mesh is valid (require_valid_mesh), and the Surface_mesh
//     build_checked_mesh makes from the reader's corner halfedges is
//     build_mesh's element for element;
//   - inconsistent_orientation is repaired by repair_orientation, or the
//     surface is non-orientable (invalid_mesh).

#include <string>
#include <vector>

#include "core/mesh_build.h"
#include "fuzz_targets.h"

namespace subdivlab::fuzz {
namespace {

bool same_reading(const Result<Mesh_buffers>& a,
                  const Result<Mesh_buffers>& b) {
  return a.status.code == b.status.code &&
         a.status.message == b.status.message &&
         a.status.line == b.status.line && same_mesh(a.value, b.value) &&
         a.value.tags.notes == b.value.tags.notes;
}

void require_accepted_mesh(const Mesh_buffers& mesh,
                           const std::vector<std::uint32_t>& halfedges) {
  require_valid_mesh(mesh, "read_mesh's mesh");
  require(halfedges.size() == mesh.face_indices.size(),
          "a corner halfedge per corner");
  Mesh checked, built;
  build_checked_mesh(mesh, halfedges, checked);
  require(build_mesh(mesh, built).ok(), "build_mesh refuses a read mesh");
  require(same_surface_mesh(checked, built),
          "build_checked_mesh differs from build_mesh");
  const Mesh_buffers back = to_buffers(built);
  require(back.positions == mesh.positions &&
              back.face_sizes == mesh.face_sizes &&
              back.face_indices == mesh.face_indices,
          "to_buffers(build_mesh(m)) is not m");
}

void fuzz_reader(const std::uint8_t* data, std::size_t size,
                 Mesh_format format) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  std::vector<std::uint32_t> fast_h, general_h;
  const Result<Mesh_buffers> fast = read_mesh(bytes, format, &fast_h);
  require_sane_status(fast.status, "read_mesh");
  const Result<Mesh_buffers> general =
      detail::read_mesh_general(bytes, format, &general_h);
  require(same_reading(fast, general),
          "read_mesh and read_mesh_general disagree",
          fast.status.message + " | " + general.status.message);
  require(fast_h == general_h,
          "read_mesh and read_mesh_general give other halfedges");
  if (fast.ok()) {
    require_accepted_mesh(fast.value, fast_h);
    return;
  }
  if (fast.status.code != Status_code::inconsistent_orientation) return;
  Read_options repair;
  repair.repair_orientation = true;
  std::vector<std::uint32_t> repaired_h;
  const Result<Mesh_buffers> repaired =
      read_mesh(bytes, format, &repaired_h, repair);
  require_sane_status(repaired.status, "read_mesh with repair_orientation");
  if (repaired.ok())
    require_accepted_mesh(repaired.value, repaired_h);
  else
    require(repaired.status.code == Status_code::invalid_mesh,
            "repair_orientation failed other than non-orientable",
            repaired.status.message);
}

}  // namespace

void fuzz_off(const std::uint8_t* data, std::size_t size) {
  fuzz_reader(data, size, Mesh_format::off);
}
void fuzz_obj(const std::uint8_t* data, std::size_t size) {
  fuzz_reader(data, size, Mesh_format::obj);
}
void fuzz_ply(const std::uint8_t* data, std::size_t size) {
  fuzz_reader(data, size, Mesh_format::ply);
}
void fuzz_stl(const std::uint8_t* data, std::size_t size) {
  fuzz_reader(data, size, Mesh_format::stl);
}

}  // namespace subdivlab::fuzz
