// Topological and geometric facts about a mesh. Owner: mesh_facts.cpp.
#pragma once

#include <array>
#include <cstddef>
#include <initializer_list>

#include "mesh_types.h"

namespace subdivlab {

struct Mesh_facts {
  std::size_t vertices = 0, edges = 0, faces = 0;
  std::size_t components = 0;     ///< connected components (by faces/edges)
  std::size_t boundaries = 0;     ///< boundary loops
  long euler_characteristic = 0;  ///< V - E + F
  long genus = 0;                 ///< (2*components - chi - boundaries) / 2
  bool closed = false;            ///< no boundary loops
  std::size_t triangles = 0, quads = 0, other_faces = 0;
  std::array<double, 3> bbox_min{}, bbox_max{};  ///< zeros for an empty mesh
  std::size_t control_edges = 0;  ///< pairs in Mesh_buffers::control_edges
};

/// Facts of a valid mesh (as built by build_mesh).
Mesh_facts compute_facts(const Mesh& mesh);

/// Facts of buffers: builds the mesh first; fails as build_mesh does.
Result<Mesh_facts> compute_facts(const Mesh_buffers& mesh);

/// Facts of `child`, refined from a mesh whose facts are `parent`, counted
/// from its buffers (no Surface_mesh): `edges` is its number of edges (the
/// render arrays count them). Every host refines a mesh into a homeomorphic
/// one, so components and boundary loops are carried from the parent and
/// the Euler characteristic stays; returns false, leaving `out` unset, when
/// the counts say otherwise (the caller then asks compute_facts).
bool refined_facts(const Mesh_buffers& child, std::size_t edges,
                   const Mesh_facts& parent, Mesh_facts& out);

/// The diagonal of the bounding box of the points of `meshes` together (0
/// without points): the scale that tolerances and distances are shares of.
double bbox_diagonal(std::initializer_list<const Mesh_buffers*> meshes);

}  // namespace subdivlab
