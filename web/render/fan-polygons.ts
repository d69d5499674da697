import type { RenderBuffers } from '../core/mesh';

/**
 * The polygons a level's fan triangles came from: the core fans each
 * polygon from its first corner (0 k k+1, in order), so a polygon is its
 * first triangle's three corners and then the last corner of each further
 * one, in the mesh's own corner order. Lets the page draw polygons (SVG)
 * from what it holds, without the mesh, which the worker keeps.
 */
export function fanPolygons(buffers: RenderBuffers): { faceSizes: Uint32Array; faceIndices: Uint32Array } {
  const { triangles, triangleFace } = buffers;
  const count = triangleFace.length;
  const faceCount = count > 0 ? triangleFace[count - 1] + 1 : 0;
  const faceSizes = new Uint32Array(faceCount);
  for (let t = 0; t < count; t++) faceSizes[triangleFace[t]]++;
  const faceIndices = new Uint32Array(count + 2 * faceCount);
  let at = 0;
  for (let t = 0; t < count; t++) {
    if (t === 0 || triangleFace[t] !== triangleFace[t - 1]) {
      faceIndices[at++] = triangles[3 * t];
      faceIndices[at++] = triangles[3 * t + 1];
    }
    faceIndices[at++] = triangles[3 * t + 2];
  }
  for (let f = 0; f < faceCount; f++) faceSizes[f] += 2;
  return { faceSizes, faceIndices };
}
