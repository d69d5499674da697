/**
 * The signed volume a closed mesh's fan triangles enclose: positive when
 * its faces turn counter-clockwise seen from outside (their normals point
 * out), negative when they point in. The viewer draws only the faces
 * turned towards the camera on a closed mesh, and this says which side
 * those are.
 */
export function signedVolume(positions: Float32Array, triangles: Uint32Array): number {
  // Sum of a · (b × c) / 6 over the triangles (divergence theorem), in double.
  let sum = 0;
  for (let t = 0; t < triangles.length; t += 3) {
    const a = 3 * triangles[t];
    const b = 3 * triangles[t + 1];
    const c = 3 * triangles[t + 2];
    const bx = positions[b];
    const by = positions[b + 1];
    const bz = positions[b + 2];
    const cx = positions[c];
    const cy = positions[c + 1];
    const cz = positions[c + 2];
    sum +=
      positions[a] * (by * cz - bz * cy) +
      positions[a + 1] * (bz * cx - bx * cz) +
      positions[a + 2] * (bx * cy - by * cx);
  }
  return sum / 6;
}
