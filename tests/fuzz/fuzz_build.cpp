// The mesh builder: build_mesh and its checks (mesh_check.h) on buffers made
// from the bytes, as the bindings hand them over from JS: a few vertices
// (small whole coordinates, or NaN, infinities, huge values), faces of 0-6
// corners whose indices may be out of range or repeated, arrays whose sizes
// may disagree, and tags. What the headers promise:
//   - build_mesh and check_buffers agree (same verdict and message), and a
//     refused build leaves the mesh empty;
//   - an accepted mesh is a valid polygon mesh with every face, its
//     to_buffers is drop_isolated_vertices of the input, and
//     build_checked_mesh from the checks' corner halfedges builds the same
//     Surface_mesh element for element;
//   - check_writable accepts what the checks accept (tags aside, which it
//     checks and they do not), and is never fooled into accepting indices
//     out of range.

#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <limits>
#include <vector>

#include "core/mesh_build.h"
#include "core/mesh_check.h"
#include "fuzz_targets.h"

namespace subdivlab::fuzz {
namespace {

double coordinate(FuzzedDataProvider& in) {
  switch (in.ConsumeIntegralInRange<int>(0, 15)) {
    case 0:
      return std::numeric_limits<double>::quiet_NaN();
    case 1:
      return std::numeric_limits<double>::infinity();
    case 2:
      return 1.7e308;
    case 3:
      return in.ConsumeFloatingPoint<double>();
    default:
      return in.ConsumeIntegralInRange<int>(-4, 4);
  }
}

Mesh_buffers buffers_from(FuzzedDataProvider& in) {
  Mesh_buffers m;
  const int vertices = in.ConsumeIntegralInRange<int>(0, 12);
  for (int i = 0; i < 3 * vertices; ++i) m.positions.push_back(coordinate(in));
  if (in.ConsumeIntegralInRange<int>(0, 31) == 0 && !m.positions.empty())
    m.positions.pop_back();
  const int faces = in.ConsumeIntegralInRange<int>(0, 12);
  const auto index = [&] {
    return in.ConsumeIntegralInRange<int>(0, 31) == 0
               ? in.ConsumeIntegral<std::uint32_t>()
               : in.ConsumeIntegralInRange<std::uint32_t>(
                     0, static_cast<std::uint32_t>(vertices));
  };
  for (int f = 0; f < faces; ++f) {
    const std::uint32_t n = in.ConsumeIntegralInRange<std::uint32_t>(0, 6);
    m.face_sizes.push_back(n);
    for (std::uint32_t c = 0; c < n; ++c) m.face_indices.push_back(index());
  }
  switch (in.ConsumeIntegralInRange<int>(0, 31)) {
    case 0:
      m.face_indices.push_back(index());
      break;
    case 1:
      if (!m.face_indices.empty()) m.face_indices.pop_back();
      break;
    case 2:
      if (!m.face_sizes.empty())
        m.face_sizes.back() = in.ConsumeIntegral<std::uint32_t>();
      break;
    default:
      break;
  }
  const int creases = in.ConsumeIntegralInRange<int>(0, 3);
  for (int i = 0; i < creases; ++i) {
    m.tags.crease_edges.push_back(index());
    m.tags.crease_edges.push_back(index());
    m.tags.crease_sharpness.push_back(
        static_cast<float>(in.ConsumeIntegralInRange<int>(-1, 11)));
  }
  const int corners = in.ConsumeIntegralInRange<int>(0, 2);
  for (int i = 0; i < corners; ++i) {
    m.tags.corner_vertices.push_back(index());
    m.tags.corner_sharpness.push_back(
        static_cast<float>(in.ConsumeIntegralInRange<int>(-1, 11)));
  }
  if (in.ConsumeBool())
    m.tags.holes.push_back(in.ConsumeIntegralInRange<std::uint32_t>(
        0, static_cast<std::uint32_t>(faces)));
  return m;
}

}  // namespace

void fuzz_build(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  const Mesh_buffers m = buffers_from(in);
  Mesh built;
  const Status s = build_mesh(m, built);
  require_sane_status(s, "build_mesh");
  std::vector<std::uint32_t> halfedges;
  const detail::Check_result check = detail::check_buffers(m, {}, &halfedges);
  require(check.status.code == s.code && check.status.message == s.message,
          "build_mesh and check_buffers disagree",
          s.message + " | " + check.status.message);
  const Status writable = check_writable(m);
  require_sane_status(writable, "check_writable");
  if (!s.ok()) {
    require(built.number_of_vertices() == 0 && built.number_of_faces() == 0,
            "a refused build left a mesh");
    // check_writable does not look at manifoldness, but an index out of
    // range or a size mismatch must stop it (write_mesh would read past).
    std::size_t corners = 0;
    for (const std::uint32_t n : m.face_sizes) corners += n;
    bool in_range =
        corners == m.face_indices.size() && m.positions.size() % 3 == 0;
    for (const std::uint32_t i : m.face_indices)
      in_range = in_range && i < m.vertex_count();
    if (!in_range)
      require(!writable.ok(),
              "check_writable accepts what write_mesh misreads");
    return;
  }
  require(CGAL::is_valid_polygon_mesh(built),
          "build_mesh built an invalid polygon mesh");
  require(built.number_of_faces() == m.face_count(), "build_mesh lost faces");
  if (!writable.ok())
    require(writable.message.rfind("tags: ", 0) == 0,
            "check_writable refuses a mesh the checks accept",
            writable.message);
  const Mesh_buffers back = to_buffers(built);
  const Mesh_buffers dropped = detail::drop_isolated_vertices(m);
  require(back.positions == dropped.positions &&
              back.face_sizes == dropped.face_sizes &&
              back.face_indices == dropped.face_indices,
          "to_buffers(build_mesh(m)) is not drop_isolated_vertices(m)");
  Mesh checked;
  build_checked_mesh(m, halfedges, checked);
  require(same_surface_mesh(built, checked),
          "build_checked_mesh differs from build_mesh");
  // The reference: Surface_mesh::add_face, face by face.
  Mesh reference;
  for (std::size_t v = 0; v < dropped.vertex_count(); ++v)
    reference.add_vertex(Point(dropped.positions[3 * v],
                               dropped.positions[3 * v + 1],
                               dropped.positions[3 * v + 2]));
  std::size_t at = 0;
  for (const std::uint32_t n : dropped.face_sizes) {
    std::vector<Mesh::Vertex_index> face;
    for (std::uint32_t c = 0; c < n; ++c)
      face.emplace_back(dropped.face_indices[at + c]);
    at += n;
    require(reference.add_face(face) != Mesh::null_face(),
            "add_face refuses a face the checks accept");
  }
  require(same_surface_mesh(built, reference),
          "build_mesh differs from add_face's mesh");
}

}  // namespace subdivlab::fuzz
