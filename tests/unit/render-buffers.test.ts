/** renderBuffers: fan triangles for the GPU and the polygon edge list (quads stay quads). */
import { beforeAll, describe, expect, it } from 'vitest';
import { initNode } from '../../web/core/init-node';
import type { Mesh } from '../../web/core/mesh';
import { renderBuffers } from '../../web/core/render-buffers';
import { meshFacts, subdivide } from '../../web/core/subdiv-core';
import { loadFixture } from './test-helpers';

beforeAll(async () => {
  await initNode();
});

function edgeSet(edges: Uint32Array): Set<string> {
  const set = new Set<string>();
  for (let i = 0; i < edges.length; i += 2) set.add(`${edges[i]}-${edges[i + 1]}`);
  return set;
}

describe('renderBuffers', () => {
  it('draws the cube as 12 triangles and 12 edges, no diagonals', () => {
    const cube = loadFixture('cube.off');
    const r = renderBuffers(cube);
    expect(r.triangles.length).toBe(36);
    expect(r.triangleFace.length).toBe(12);
    expect(Array.from(r.triangleFace)).toEqual([0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5]);
    expect(r.edges.length).toBe(24);
    expect(edgeSet(r.edges).size).toBe(12);
    // Every edge joins two corners that differ in exactly one coordinate: a cube edge, not a diagonal.
    for (let i = 0; i < r.edges.length; i += 2) {
      const a = r.edges[i];
      const b = r.edges[i + 1];
      let differing = 0;
      for (let k = 0; k < 3; k++) if (cube.positions[3 * a + k] !== cube.positions[3 * b + k]) differing++;
      expect(differing).toBe(1);
    }
    expect(r.positions).toBeInstanceOf(Float32Array);
    expect(Array.from(r.positions)).toEqual(Array.from(cube.positions));
  });

  it('fans each polygon from its first corner, keeping its orientation', () => {
    const pentagon: Mesh = {
      positions: new Float64Array([1, 0, 0, 0.3, 0.95, 0, -0.8, 0.6, 0, -0.8, -0.6, 0, 0.3, -0.95, 0]),
      faceSizes: new Uint32Array([5]),
      faceIndices: new Uint32Array([0, 1, 2, 3, 4]),
      controlEdges: new Uint32Array(0),
    };
    const r = renderBuffers(pentagon);
    expect(Array.from(r.triangles)).toEqual([0, 1, 2, 0, 2, 3, 0, 3, 4]);
    expect(Array.from(r.triangleFace)).toEqual([0, 0, 0]);
    expect(Array.from(r.edges)).toEqual([0, 1, 1, 2, 2, 3, 3, 4, 0, 4]);
  });

  it.each(['mixed-open.off', 'torus-quad.off', 'rhombicuboctahedron.off'])(
    'on %s and its Catmull-Clark level 2: edges = the facts edges, triangles = Σ(degree - 2)',
    (fixture) => {
      const base = loadFixture(fixture);
      for (const mesh of [base, subdivide(base, { scheme: 'catmull-clark', levels: 2 })]) {
        const r = renderBuffers(mesh);
        const facts = meshFacts(mesh);
        expect(r.edges.length / 2).toBe(facts.edges);
        expect(edgeSet(r.edges).size).toBe(facts.edges);
        const expectedTriangles = Array.from(mesh.faceSizes).reduce((s, k) => s + k - 2, 0);
        expect(r.triangles.length / 3).toBe(expectedTriangles);
        expect(Math.max(...r.triangles)).toBeLessThan(facts.vertices);
      }
    },
  );
});
