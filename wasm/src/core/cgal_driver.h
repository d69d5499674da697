// CGAL's hosts' driver: a Surface_mesh built and checked
// (subdivide_prepare.h), refined one step at a time by
// Subdivision_method_3 -- Doo-Sabin on open meshes by the border-aware DQQ
// host of dqq_border_3.h, sqrt(3) refining the border on every second step
// (the parity carried through Subdivide_options::start_level),
// quad-triangle by quad_triangle_3.h, custom rules by custom_rules.h --
// each step checked against the memory limit first, then back to buffers.
// The reference the fast hosts are tested against (option cgal_hosts), and
// the route of the schemes without one. Internal to the core (subdivide.h
// is the API). Owner: cgal_driver.cpp.

#pragma once

#include "mesh_types.h"
#include "subdivide.h"

namespace subdivlab::detail {

/// Runs `options` on CGAL's hosts from `in` (`input`: its bytes) into
/// `out`; `level` follows the steps for messages. May throw (CGAL,
/// bad_alloc): subdivide_mesh catches.
Status run_cgal_hosts(const Mesh_buffers& in, const Subdivide_options& options,
                      double input, Mesh_buffers& out, int& level);

}  // namespace subdivlab::detail
