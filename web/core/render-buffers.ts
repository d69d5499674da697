import type { Mesh, RenderBuffers } from './mesh';

/**
 * What the GPU draws for `mesh`: float32 positions, each polygon fanned into
 * triangles from its first corner (with the polygon each triangle came from),
 * and every polygon edge once — quads stay quads, the fan's diagonals are not
 * edges. Pure TypeScript; the mesh is not changed.
 */
export function renderBuffers(mesh: Mesh): RenderBuffers {
  const { faceSizes, faceIndices } = mesh;
  let triangleCount = 0;
  for (const size of faceSizes) triangleCount += size - 2;

  const triangles = new Uint32Array(triangleCount * 3);
  const triangleFace = new Uint32Array(triangleCount);
  const edgeList: number[] = [];
  // An edge a–b is kept once, keyed by its smaller then larger end.
  const seen = new Set<number>();
  const vertexCount = mesh.positions.length / 3;

  let offset = 0;
  let t = 0;
  for (let f = 0; f < faceSizes.length; f++) {
    const size = faceSizes[f];
    const first = faceIndices[offset];
    for (let k = 1; k + 1 < size; k++) {
      triangles[3 * t] = first;
      triangles[3 * t + 1] = faceIndices[offset + k];
      triangles[3 * t + 2] = faceIndices[offset + k + 1];
      triangleFace[t] = f;
      t++;
    }
    for (let k = 0; k < size; k++) {
      const a = faceIndices[offset + k];
      const b = faceIndices[offset + ((k + 1) % size)];
      const lo = Math.min(a, b);
      const hi = Math.max(a, b);
      const key = lo * vertexCount + hi;
      if (!seen.has(key)) {
        seen.add(key);
        edgeList.push(lo, hi);
      }
    }
    offset += size;
  }

  return {
    positions: Float32Array.from(mesh.positions),
    triangles,
    edges: Uint32Array.from(edgeList),
    triangleFace,
  };
}
