/**
 * The discrete curvature through the real WebAssembly core (the binding and
 * its arrays): the cube's corners, a flat grid, a sphere-like mesh and
 * Gauss-Bonnet, the figures worked out by hand (tests/core/test_curvature.cpp
 * checks the formulas natively).
 */
import { beforeAll, describe, expect, it } from 'vitest';
import { initNode } from '../../web/core/init-node';
import type { Mesh } from '../../web/core/mesh';
import { subdivide, vertexCurvature } from '../../web/core/subdiv-core';
import { SubdivError } from '../../web/core/subdiv-error';
import { loadFixture } from './test-helpers';

beforeAll(async () => {
  await initNode();
});

const sum = (values: Float64Array) => values.reduce((s, x) => s + x, 0);

/** `mesh` with every vertex pushed out from the origin to radius `r`. */
function onSphere(mesh: Mesh, r: number): Mesh {
  const positions = mesh.positions.slice();
  for (let v = 0; v < positions.length; v += 3) {
    const s = r / Math.hypot(positions[v], positions[v + 1], positions[v + 2]);
    for (let i = 0; i < 3; i++) positions[v + i] *= s;
  }
  return { ...mesh, positions };
}

describe('vertexCurvature', () => {
  it('gives each corner of the cube [-1,1]³ a defect of π/2 and area 3 (K = π/6), 4π in all', () => {
    const c = vertexCurvature(loadFixture('cube.off'));
    expect(c.borderVertices).toBe(0);
    for (let v = 0; v < 8; v++) {
      expect(c.angleDefect[v]).toBeCloseTo(Math.PI / 2, 14);
      expect(c.area[v]).toBeCloseTo(3, 12);
      expect(c.gaussian[v]).toBeCloseTo(Math.PI / 6, 12);
    }
    expect(Math.abs(sum(c.angleDefect) - 4 * Math.PI)).toBeLessThan(1e-12);
  });

  it('leaves the 12 border vertices of the open 3 × 3 grid out (NaN) and gives its 4 inner ones 0', () => {
    const c = vertexCurvature(loadFixture('grid-open.off'));
    expect(c.borderVertices).toBe(12);
    const inner = [...c.gaussian.keys()].filter((v) => !Number.isNaN(c.gaussian[v]));
    expect(inner).toEqual([5, 6, 9, 10]);
    for (const v of inner) {
      expect(c.gaussian[v]).toBe(0);
      expect(c.mean[v]).toBe(0);
    }
    expect(c.mean.filter((x) => Number.isNaN(x))).toHaveLength(12);
  });

  it('gives a sphere of radius 2 (an icosahedron split three times) K ≈ 1/4 and H ≈ 1/2 at all 642 vertices', () => {
    const sphere = onSphere(subdivide(loadFixture('icosahedron.off'), { scheme: 'linear-tri', levels: 3 }), 2);
    const c = vertexCurvature(sphere);
    expect(c.gaussian).toHaveLength(642);
    for (let v = 0; v < 642; v++) {
      expect(Math.abs(c.gaussian[v] * 4 - 1)).toBeLessThan(0.01);
      expect(Math.abs(c.mean[v] * 2 - 1)).toBeLessThan(0.005);
    }
    expect(Math.abs(sum(c.angleDefect) - 4 * Math.PI)).toBeLessThan(1e-12);
  });

  it('sums the defects of a torus (χ = 0) to 0 after two Catmull-Clark steps', () => {
    const c = vertexCurvature(subdivide(loadFixture('torus-quad.off'), { scheme: 'catmull-clark', levels: 2 }));
    expect(c.borderVertices).toBe(0);
    expect(Math.abs(sum(c.angleDefect))).toBeLessThan(1e-11);
    expect(c.gaussian.some((k) => k > 0) && c.gaussian.some((k) => k < 0)).toBe(true);
  });

  it('refuses a face that names a missing vertex, with a message that says so', () => {
    const cube = loadFixture('cube.off');
    const bad = { ...cube, faceIndices: cube.faceIndices.slice() };
    bad.faceIndices[0] = 9;
    expect(() => vertexCurvature(bad)).toThrow(SubdivError);
    expect(() => vertexCurvature(bad)).toThrow('A face names vertex 9 of a mesh with 8 vertices.');
  });
});
