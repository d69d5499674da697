/**
 * The signed volume that tells the viewer which faces of a closed level
 * face the camera: worked by hand for the cube and a tetrahedron, and its
 * sign for a refined level and for the same faces turned inside out.
 */
import { beforeAll, describe, expect, it } from 'vitest';
import { initNode } from '../../web/core/init-node';
import { signedVolume } from '../../web/core/signed-volume';
import { subdivideForView, viewMesh } from '../../web/core/subdiv-core';
import { loadFixture } from './test-helpers';

beforeAll(async () => {
  await initNode();
});

/** The same triangles, each with two corners swapped: normals pointing the other way. */
function flipped(triangles: Uint32Array): Uint32Array {
  const out = triangles.slice();
  for (let t = 0; t < out.length; t += 3) [out[t + 1], out[t + 2]] = [out[t + 2], out[t + 1]];
  return out;
}

describe('signedVolume', () => {
  it('is 8 for the cube [-1, 1]³ as the core fans it, and −8 turned inside out', () => {
    const { buffers } = viewMesh(loadFixture('cube.off'));
    expect(signedVolume(buffers.positions, buffers.triangles)).toBeCloseTo(8, 12);
    expect(signedVolume(buffers.positions, flipped(buffers.triangles))).toBeCloseTo(-8, 12);
  });

  it('is 1/6 for the corner tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1) with outward faces', () => {
    const positions = new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1]);
    // Counter-clockwise seen from outside.
    const triangles = new Uint32Array([0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3]);
    expect(signedVolume(positions, triangles)).toBeCloseTo(1 / 6, 7);
    expect(signedVolume(positions, flipped(triangles))).toBeCloseTo(-1 / 6, 7);
  });

  it('stays positive and below the control cube’s 8 after two Catmull-Clark steps', () => {
    const cube = loadFixture('cube.off');
    const parent = viewMesh(cube).facts;
    const { buffers, facts } = subdivideForView(cube, { scheme: 'catmull-clark', levels: 2 }, parent);
    expect(facts.closed).toBe(true);
    const volume = signedVolume(buffers.positions, buffers.triangles);
    // Catmull-Clark's surface lies inside the convex control cube, its faces still turned out.
    expect(volume).toBeGreaterThan(0);
    expect(volume).toBeLessThan(8);
  });
});
