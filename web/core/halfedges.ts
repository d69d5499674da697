/**
 * The halfedge structure of a mesh as CGAL's Surface_mesh numbers it
 * (wasm/src/core/halfedges.h), the table `subdiv halfedges` prints and the
 * structure students check their own implementation against.
 */
import type { Mesh, MeshFacts } from './mesh';

/** Per halfedge h (index into every array); opposite[h] is h ^ 1. */
export interface HalfedgeTable {
  next: Uint32Array;
  prev: Uint32Array;
  opposite: Uint32Array;
  /** The vertex h points to (CGAL's target). */
  target: Uint32Array;
  /** The face h bounds; −1 on a border halfedge. */
  face: Int32Array;
}

/** CGAL's Euler operators (wasm/src/core/euler_ops.h), by their CGAL names. */
export type EulerOperator =
  | 'split_face'
  | 'join_face'
  | 'add_center_vertex'
  | 'remove_center_vertex'
  | 'split_edge'
  | 'flip_edge';

/** The mesh after one operator, its facts, CGAL's validity, and the halfedge the operator returned. */
export interface EulerResult {
  mesh: Mesh;
  facts: MeshFacts;
  valid: boolean;
  halfedge: number;
}

/** One √3 step by Euler operators, stopped after `done` of its `total` operators; `last` names the last one. */
export interface Sqrt3Walk {
  mesh: Mesh;
  done: number;
  total: number;
  last: string;
}
