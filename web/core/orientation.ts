/**
 * Which way a closed mesh's faces turn: the viewer draws only the faces
 * turned towards the camera on such a mesh, and this says which those are.
 */
import type { Mesh, MeshFacts } from './mesh';

/**
 * The volume a mesh's polygons enclose, signed: positive when they turn
 * counter-clockwise seen from outside (their normals point out), negative
 * when they point in. Meaningful for a closed mesh.
 */
export function signedVolume(mesh: Mesh): number {
  // Sum of a · (b × c) / 6 over each polygon's fan triangles (divergence theorem).
  const { positions: p, faceSizes, faceIndices } = mesh;
  let sum = 0;
  let corner = 0;
  for (const size of faceSizes) {
    const a = 3 * faceIndices[corner];
    for (let k = 1; k + 1 < size; k++) {
      const b = 3 * faceIndices[corner + k];
      const c = 3 * faceIndices[corner + k + 1];
      sum +=
        p[a] * (p[b + 1] * p[c + 2] - p[b + 2] * p[c + 1]) +
        p[a + 1] * (p[b + 2] * p[c] - p[b] * p[c + 2]) +
        p[a + 2] * (p[b] * p[c + 1] - p[b + 1] * p[c]);
    }
    corner += size;
  }
  return sum / 6;
}

/**
 * +1 when `mesh` is one closed piece whose faces turn outward, −1 when
 * they turn inward, 0 otherwise (open, several pieces — each may turn its
 * own way —, or enclosing next to no volume): then both sides are drawn.
 * Every scheme keeps the way faces turn, so a level's is its parent's.
 */
export function orientation(mesh: Mesh, facts: MeshFacts): -1 | 0 | 1 {
  if (!facts.closed || facts.components !== 1) return 0;
  const volume = signedVolume(mesh);
  const size = Math.max(...facts.bboxMax.map((max, i) => max - facts.bboxMin[i]));
  // A flat closed shape encloses nothing: its sign says nothing.
  if (!(Math.abs(volume) > 1e-9 * size ** 3)) return 0;
  return volume > 0 ? 1 : -1;
}
