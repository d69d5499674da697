/**
 * Which way a level's faces turn, for the viewer's one-sided drawing of
 * closed meshes: signed volumes worked by hand (cube, corner tetrahedron),
 * the same faces turned inside out, and the cases drawn on both sides.
 */
import { beforeAll, describe, expect, it } from 'vitest';
import { initNode } from '../../web/core/init-node';
import type { Mesh } from '../../web/core/mesh';
import { orientation, signedVolume } from '../../web/core/orientation';
import { meshFacts, subdivide } from '../../web/core/subdiv-core';
import { loadFixture } from './test-helpers';

beforeAll(async () => {
  await initNode();
});

/** The same polygons with their corners in the opposite order. */
function insideOut(mesh: Mesh): Mesh {
  const faceIndices = mesh.faceIndices.slice();
  let corner = 0;
  for (const size of mesh.faceSizes) {
    faceIndices.subarray(corner, corner + size).reverse();
    corner += size;
  }
  return { ...mesh, faceIndices };
}

const TETRAHEDRON: Mesh = {
  positions: new Float64Array([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1]),
  faceSizes: new Uint32Array([3, 3, 3, 3]),
  // Counter-clockwise seen from outside.
  faceIndices: new Uint32Array([0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3]),
  controlEdges: new Uint32Array(0),
};

describe('signedVolume and orientation', () => {
  it('the cube [-1, 1]³ with outward quads: 8, turned outward; inside out: −8, inward', () => {
    const cube = loadFixture('cube.off');
    expect(signedVolume(cube)).toBeCloseTo(8, 12);
    expect(orientation(cube, meshFacts(cube))).toBe(1);
    const inverted = insideOut(cube);
    expect(signedVolume(inverted)).toBeCloseTo(-8, 12);
    expect(orientation(inverted, meshFacts(inverted))).toBe(-1);
  });

  it('the corner tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1): 1/6', () => {
    expect(signedVolume(TETRAHEDRON)).toBeCloseTo(1 / 6, 14);
    expect(signedVolume(insideOut(TETRAHEDRON))).toBeCloseTo(-1 / 6, 14);
    expect(orientation(TETRAHEDRON, meshFacts(TETRAHEDRON))).toBe(1);
  });

  it('keeps its sign through two Catmull-Clark steps (inside the convex control cube)', () => {
    const level2 = subdivide(loadFixture('cube.off'), { scheme: 'catmull-clark', levels: 2 });
    const volume = signedVolume(level2);
    expect(volume).toBeGreaterThan(0);
    expect(volume).toBeLessThan(8);
    expect(orientation(insideOut(level2), meshFacts(level2))).toBe(-1);
  });

  it('is 0 (both sides drawn) for an open mesh and for two pieces', () => {
    const grid = loadFixture('grid-open.off');
    expect(meshFacts(grid).closed).toBe(false);
    expect(orientation(grid, meshFacts(grid))).toBe(0);
    const two = loadFixture('two-tetrahedra.off');
    expect(meshFacts(two)).toMatchObject({ closed: true, components: 2 });
    expect(orientation(two, meshFacts(two))).toBe(0);
  });
});
