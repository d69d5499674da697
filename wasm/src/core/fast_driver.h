// The fast hosts' driver (refine/): level 0 from the checked buffers, or
// from CGAL's mesh when polygons must be triangulated first; its tags and
// marked control edges; then the steps of one host, each checked against
// the memory limit first; the last level's arrays moved into the result.
// Internal to the core (subdivide.h is the API). Owner: fast_driver.cpp.

#pragma once

#include <string>

#include "mesh_types.h"
#include "stencils.h"
#include "subdivide.h"

namespace subdivlab::detail {

/// What step_stencils asks of a run: the stencils of its last step
/// (stencils.h), or why there are none.
struct Stencil_request {
  Stencil_table table;
  std::string error;
};

/// Whether `options` run on a fast host: a scheme (or custom host) that has
/// one, CGAL's hosts not asked for, and at least one step.
bool runs_fast(const Subdivide_options& options);

/// Runs `options` on their fast host from `in` (`input`: its bytes, held
/// beside the steps) into `out`; `level` follows the steps for messages;
/// with `stencils`, the last step's stencils too. May throw (bad_alloc):
/// subdivide_mesh catches.
Status run_fast_hosts(const Mesh_buffers& in, const Subdivide_options& options,
                      double input, Mesh_buffers& out, int& level,
                      Stencil_request* stencils);

}  // namespace subdivlab::detail
