/**
 * A control vertex's basis function at a refined level: its weight in every
 * refined vertex through all steps. The first step's weights are its
 * stencils (stencils.ts; a triangulation that step makes is made on the
 * real points). Every scheme's points are linear in the points they start
 * from, coordinate by coordinate, so the later steps run on level 1 with x
 * replaced by those weights give the basis function as the result's x (y
 * and z stay the real ones). The steps are the viewer's: one at a time, so
 * the values are numbered as its levels are.
 */
import type { Mesh, SubdivideOptions } from './mesh';
import { stepStencils, subdivide } from './subdiv-core';

/** The step options of a level: `options` with levels 1 and its start level. */
export type StepOptions = Omit<SubdivideOptions, 'levels' | 'startLevel'>;

/**
 * The basis function of control vertex `vertex` of `mesh` (level 0) at level
 * `levels`, one value per vertex of that level; `options` are each step's.
 */
export function basisFunction(mesh: Mesh, vertex: number, levels: number, options: StepOptions): Float64Array {
  const count = mesh.positions.length / 3;
  if (!Number.isInteger(vertex) || vertex < 0 || vertex >= count) {
    throw new RangeError(`vertex ${vertex} is not a control vertex (0 to ${count - 1})`);
  }
  if (levels === 0) return Float64Array.from({ length: count }, (_, v) => (v === vertex ? 1 : 0));
  const first = { ...options, levels: 1, startLevel: 0 };
  const table = stepStencils(mesh, first);
  const level1 = subdivide(mesh, first);
  const positions = Float64Array.from(level1.positions);
  for (let c = 0; c < table.kinds.length; ++c) {
    positions[3 * c] = 0;
    for (let i = table.offsets[c]; i < table.offsets[c + 1]; ++i)
      if (table.parents[i] === vertex) positions[3 * c] = table.weights[i];
  }
  let level: Mesh = { ...level1, positions };
  for (let k = 1; k < levels; ++k) level = subdivide(level, { ...options, levels: 1, startLevel: k });
  const values = new Float64Array(level.positions.length / 3);
  for (let v = 0; v < values.length; ++v) values[v] = level.positions[3 * v];
  return values;
}
