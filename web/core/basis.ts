/**
 * A control vertex's basis function at a refined level: its weight in every
 * refined vertex through all steps. Every scheme's points are linear in the
 * control points, coordinate by coordinate, so the steps run on the control
 * mesh with x replaced by 1 at that vertex and 0 elsewhere give the basis
 * function as the result's x (y and z stay the real ones, so the mesh keeps
 * its shape for the core's checks). The steps are the viewer's: one at a
 * time, so the values are numbered as its levels are.
 */
import type { Mesh, SubdivideOptions } from './mesh';
import { subdivide } from './subdiv-core';

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
  const positions = Float64Array.from(mesh.positions);
  for (let v = 0; v < count; ++v) positions[3 * v] = v === vertex ? 1 : 0;
  let level: Mesh = { ...mesh, positions };
  for (let k = 0; k < levels; ++k) level = subdivide(level, { ...options, levels: 1, startLevel: k });
  const values = new Float64Array(level.positions.length / 3);
  for (let v = 0; v < values.length; ++v) values[v] = level.positions[3 * v];
  return values;
}
