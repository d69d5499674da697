// Orientation of a polygon soup by CGAL, applied without its cuts. Owner of
// orientation_repair.h.

#include "orientation_repair.h"

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace subdivlab::detail {
namespace {

/// Collects the polygons orient_polygon_soup reverses (a polygon reversed
/// twice is back as it was).
struct Reversal_visitor
    : CGAL::Polygon_mesh_processing::Default_orientation_visitor {
  std::vector<char>* reversed = nullptr;
  void polygon_orientation_reversed(std::size_t p) { (*reversed)[p] ^= 1; }
};

/// Which faces CGAL's orientation reverses (1) and which it keeps (0).
std::vector<char> faces_to_reverse(const Mesh_buffers& mesh) {
  // orient_polygon_soup wants points and index polygons it may append to;
  // the appended points (its cuts) are dropped with these copies.
  std::vector<Point> points;
  points.reserve(mesh.vertex_count());
  for (std::size_t i = 0; i + 2 < mesh.positions.size(); i += 3)
    points.emplace_back(mesh.positions[i], mesh.positions[i + 1],
                        mesh.positions[i + 2]);
  std::vector<std::vector<std::size_t>> polygons(mesh.face_count());
  std::size_t o = 0;
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    const std::uint32_t k = mesh.face_sizes[f];
    polygons[f].assign(mesh.face_indices.begin() + o,
                       mesh.face_indices.begin() + o + k);
    o += k;
  }
  std::vector<char> reversed(polygons.size(), 0);
  Reversal_visitor visitor;
  visitor.reversed = &reversed;
  CGAL::Polygon_mesh_processing::orient_polygon_soup(
      points, polygons, CGAL::parameters::visitor(visitor));
  return reversed;
}

}  // namespace

std::string reversed_note(std::size_t reversed) {
  return "orientation repaired: " + std::to_string(reversed) +
         (reversed == 1 ? " face was" : " faces were") +
         " reversed to agree with their neighbours";
}

Check_result check_orientation(Mesh_buffers& mesh, const Check_naming& naming,
                               std::vector<std::uint32_t>* corner_halfedges,
                               bool repair, std::size_t& reversed) {
  reversed = 0;
  Check_result first = check_buffers(mesh, naming, corner_halfedges);
  if (!first.inconsistent_orientation) return first;
  std::vector<char> flip = faces_to_reverse(mesh);
  // Reversing every face's choice agrees as well; the fewer reversals keep
  // more of the file as it was (a cube with one face flipped gets that face
  // turned, not the other five).
  const std::size_t chosen =
      static_cast<std::size_t>(std::count(flip.begin(), flip.end(), 1));
  if (2 * chosen > flip.size())
    for (char& c : flip) c ^= 1;
  Mesh_buffers turned = mesh;
  std::size_t o = 0, count = 0;
  for (std::size_t f = 0; f < flip.size(); ++f) {
    const std::uint32_t k = mesh.face_sizes[f];
    if (flip[f]) {
      std::reverse(turned.face_indices.begin() + o,
                   turned.face_indices.begin() + o + k);
      ++count;
    }
    o += k;
  }
  Check_result again = check_buffers(turned, naming, corner_halfedges);
  if (again.inconsistent_orientation) {
    // "line 9: inconsistent orientation: the faces ... direction" becomes
    // "line 9: the surface is non-orientable (like a Möbius strip): the
    // faces ... direction, whichever way each face is turned".
    std::string& m = first.status.message;
    const std::string was = "inconsistent orientation: ";
    const std::size_t at = m.find(was);
    if (at != std::string::npos)
      m.replace(at, was.size(),
                "the surface is non-orientable (like a M\u00f6bius strip): ");
    m += ", whichever way each face is turned";
    first.status.code = Status_code::invalid_mesh;
    return first;
  }
  if (!repair) {
    // The repaired check's corner halfedges are not this (failed) result's.
    if (corner_halfedges) corner_halfedges->clear();
    first.status.code = Status_code::inconsistent_orientation;
    first.status.message += "; turning " + std::to_string(count) +
                            (count == 1 ? " face" : " faces") +
                            " around makes them agree (repair orientation)";
    return first;
  }
  mesh = std::move(turned);
  reversed = count;
  return again;
}

Result<Mesh_buffers> finish_read(Mesh_buffers&& mesh,
                                 const Check_naming& naming,
                                 std::vector<std::uint32_t>* corner_halfedges,
                                 bool repair_orientation) {
  Result<Mesh_buffers> r;
  std::size_t reversed = 0;
  Check_result check = check_orientation(mesh, naming, corner_halfedges,
                                         repair_orientation, reversed);
  if (!check.status.ok()) {
    r.status = std::move(check.status);
    return r;
  }
  if (reversed > 0) mesh.tags.notes.push_back(reversed_note(reversed));
  r.value = drop_isolated_vertices(std::move(mesh));
  return r;
}

}  // namespace subdivlab::detail
