// The points of a DQQ step: one pass over the parent's corners, face by
// face, each writing the child vertex dual_hosts.h gave the corner (closed:
// the child's F-face of the face lists them; open:
// Dual_scratch::corner_vertex). Owner: dual_points.cpp.
#pragma once

#include <cstdint>

#include "dual_hosts.h"
#include "dual_masks.h"
#include "refine_level.h"

namespace subdivlab {
namespace refine {

/// Degree of the first face of `parent` (in face order) that `mask` has no
/// weights for, or 0 when it covers them all (custom tables end somewhere).
std::uint32_t dual_uncovered_degree(const Level& parent, const Dual_mask& mask);

/// child.positions from `parent`, after refine_dqq_topology(parent,
/// scratch, child). Precondition: dual_uncovered_degree returned 0.
void refine_dual_points(const Level& parent, const Dual_mask& mask,
                        const Dual_scratch& scratch, Level& child);

}  // namespace refine
}  // namespace subdivlab
