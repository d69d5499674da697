/**
 * Basis functions through the real core (web/core/basis.ts): a partition of
 * unity at every refined vertex, they reproduce the refined points, and on
 * regular meshes they reach exactly the vertices of the scheme's known
 * support at that level (towards the cubic B-spline's 4 × 4 faces for
 * Catmull-Clark, the quartic box spline's two rings for Loop).
 */
import { beforeAll, describe, expect, it } from 'vitest';
import { basisFunction } from '../../web/core/basis';
import { initNode } from '../../web/core/init-node';
import type { SchemeName } from '../../web/core/mesh';
import { subdivide } from '../../web/core/subdiv-core';
import { loadFixture } from './test-helpers';

beforeAll(async () => {
  await initNode();
});

describe('basisFunction', () => {
  const cases: [string, SchemeName][] = [
    ['cube.off', 'catmull-clark'],
    ['grid-open.off', 'catmull-clark'],
    ['octahedron.off', 'loop'],
    ['disk-tri.off', 'loop'],
    ['disk-tri.off', 'sqrt3'],
    ['cube.off', 'doo-sabin'],
    ['mixed-open.off', 'quad-triangle'],
  ];
  for (const [name, scheme] of cases) {
    it(`${scheme} on ${name}: a partition of unity at level 2 that gives the level's points`, () => {
      const mesh = loadFixture(name);
      const level2 = subdivide(subdivide(mesh, { scheme, levels: 1 }), { scheme, levels: 1, startLevel: 1 });
      const count = mesh.positions.length / 3;
      const n = level2.positions.length / 3;
      const sum = new Float64Array(n);
      const point = new Float64Array(3 * n);
      for (let i = 0; i < count; ++i) {
        const b = basisFunction(mesh, i, 2, { scheme });
        expect(b.length).toBe(n);
        for (let v = 0; v < n; ++v) {
          sum[v] += b[v];
          for (let c = 0; c < 3; ++c) point[3 * v + c] += b[v] * mesh.positions[3 * i + c];
        }
      }
      let worst = 0;
      for (let v = 0; v < n; ++v) {
        worst = Math.max(worst, Math.abs(sum[v] - 1));
        for (let c = 0; c < 3; ++c) worst = Math.max(worst, Math.abs(point[3 * v + c] - level2.positions[3 * v + c]));
      }
      expect(worst).toBeLessThan(1e-12);
    });
  }

  it("reaches the scheme's support at level 2 on regular meshes", () => {
    const reached = (name: string, scheme: SchemeName) =>
      Array.from(basisFunction(loadFixture(name), 0, 2, { scheme })).filter((x) => Math.abs(x) > 1e-12).length;
    // A step's masks reach one ring of the level before, so after k steps a control vertex reaches
    // 1 + 1/2 + ... + 1/2^(k-1) control rings (2 in the limit: the bicubic B-spline's 4 x 4 faces,
    // the quartic box spline's two-ring hexagon). At level 2, 1.5 rings = 6 steps of a quarter.
    // Catmull-Clark: the 13 x 13 vertices at most 6 steps away in each direction.
    expect(reached('torus-quad.off', 'catmull-clark')).toBe(13 * 13);
    // Loop: the vertices at most 6 steps away, 1 + 6 (1 + 2 + ... + 6).
    expect(reached('torus-tri.off', 'loop')).toBe(1 + 6 * 21);
  });

  it('triangulating first (Loop on the cube) is done on the real points: still a partition of unity', () => {
    const mesh = loadFixture('cube.off');
    const options = { scheme: 'loop' as SchemeName, triangulate: true };
    const level2 = subdivide(subdivide(mesh, { ...options, levels: 1 }), { ...options, levels: 1, startLevel: 1 });
    const sum = new Float64Array(level2.positions.length / 3);
    const point = new Float64Array(level2.positions.length);
    for (let i = 0; i < 8; ++i) {
      const b = basisFunction(mesh, i, 2, options);
      for (let v = 0; v < sum.length; ++v) {
        sum[v] += b[v];
        for (let c = 0; c < 3; ++c) point[3 * v + c] += b[v] * mesh.positions[3 * i + c];
      }
    }
    for (let v = 0; v < sum.length; ++v) {
      expect(sum[v]).toBeCloseTo(1, 12);
      for (let c = 0; c < 3; ++c) expect(point[3 * v + c]).toBeCloseTo(level2.positions[3 * v + c], 12);
    }
  });

  it('refuses a vertex that is not a control vertex', () => {
    expect(() => basisFunction(loadFixture('cube.off'), 8, 1, { scheme: 'catmull-clark' })).toThrow(
      'vertex 8 is not a control vertex (0 to 7)',
    );
  });
});
