/**
 * The halfedge structure of a mesh as CGAL's Surface_mesh numbers it
 * (wasm/src/core/halfedges.h), the table `subdiv halfedges` prints and the
 * structure students check their own implementation against.
 */

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
