// What both routes of a run (fast_driver.h, cgal_driver.h) check and
// prepare before their steps, and the refusals they share: the options, a
// mesh of polygons given to a scheme of triangles, interior vertices of two
// edges, sqrt(3)'s border parity, points that overflow; CGAL's mesh of the
// input, triangulated when asked. Internal to the core (subdivide.h is the
// API). Owner: subdivide_prepare.cpp.

#pragma once

#include <string>

#include "mesh_types.h"
#include "refine/crease.h"
#include "refine/refine_level.h"
#include "size_model.h"
#include "subdivide.h"

namespace subdivlab::detail {

/// The scheme known, the levels and start level not negative, custom rules
/// well formed.
Status check_options(const Subdivide_options& options);

/// The refusal of a scheme of triangles on a mesh with other faces.
Status not_triangles(const std::string& scheme, const Counts& c);

/// Frees the elements a host removed (CGAL's DQQ removes the old vertices;
/// sqrt3's flips recycle what they remove). Not shrink_to_fit: it copies
/// every array, a peak above most steps', and the next step's reserve
/// reallocates anyway. collect_garbage shrinks the arrays itself.
void collect_removed(Mesh& mesh);

/// The refusal of a vertex of two edges by the schemes it would break
/// (see subdivide_prepare.cpp), on a level of a fast host.
Status check_two_valent_vertices(const refine::Level& l,
                                 const Subdivide_options& options);

/// Builds and checks the mesh the steps start from: valid, and triangles for
/// the schemes that need them (triangulated here if asked to).
Status prepare(const Mesh_buffers& in, const Subdivide_options& options,
               Mesh& mesh, Counts& counts);

/// The refusal of a border step (sqrt3 or custom rules on its host) on a
/// mesh with `multi` faces that have more than one border edge: the host
/// assumes at most one, which holds for the output of a non-border step
/// but not for arbitrary input.
Status sqrt3_border_refusal(const Subdivide_options& options, int global_step,
                            double multi);

/// Averaging overflows near the largest double: a file's 1e308 is finite and
/// accepted, but a sum of such coordinates is not (and custom weights can be
/// large too). A step must not hand out inf or nan, which no file can hold.
Status overflow(const Mesh_buffers& in, const std::string& scheme, int level);

/// Whether a run applies OpenSubdiv's creasing: a scheme that applies tags
/// (applies_creases) on a mesh with tags, or with a border mode other than
/// CGAL's; `creasing` gets the tags' options overridden by the run's.
bool creasing_of(const Mesh_buffers& in, const Subdivide_options& options,
                 refine::Creasing& creasing);

}  // namespace subdivlab::detail
