// Faces turned inconsistently: told apart from a non-orientable surface,
// and turned to agree on request. Internal to the core (the readers call
// it). Owner: orientation_repair.cpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "mesh_check.h"
#include "mesh_types.h"

namespace subdivlab::detail {

/// check_buffers(mesh, naming, corner_halfedges), and when its complaint is
/// an edge two faces use in the same direction, CGAL's polygon-soup
/// orientation (Polygon_mesh_processing::orient_polygon_soup) is asked which
/// faces to reverse:
/// - if reversing them does not make the faces agree, the surface is
///   non-orientable (a Möbius strip): invalid_mesh, saying so;
/// - otherwise, with `repair`, those faces are reversed in `mesh`,
///   `reversed` receives their number and the result is the check of the
///   repaired mesh; without `repair` the status is inconsistent_orientation,
///   saying that the faces can be turned to agree.
/// orient_polygon_soup would also duplicate vertices to cut a non-orientable
/// or pinched surface apart; those duplicates are not used: the surface is
/// never cut.
Check_result check_orientation(Mesh_buffers& mesh, const Check_naming& naming,
                               std::vector<std::uint32_t>* corner_halfedges,
                               bool repair, std::size_t& reversed);

/// The note a reader leaves when it reversed `reversed` faces.
std::string reversed_note(std::size_t reversed);

/// The end of the PLY and STL readers (OFF and OBJ add their tags between):
/// check_orientation with faces named by `naming`, the note of a repair, the
/// vertices no face uses dropped.
Result<Mesh_buffers> finish_read(Mesh_buffers&& mesh,
                                 const Check_naming& naming,
                                 std::vector<std::uint32_t>* corner_halfedges,
                                 bool repair_orientation);

}  // namespace subdivlab::detail
