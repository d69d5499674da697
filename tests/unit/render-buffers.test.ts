/**
 * A level as the viewer takes it, from the core (viewMesh, subdivideForView):
 * fan triangles, the polygon edge list (quads stay quads), normals, and the
 * facts of a step equal to the facts computed afresh.
 */
import { beforeAll, describe, expect, it } from 'vitest';
import { initNode } from '../../web/core/init-node';
import type { Mesh, SchemeName } from '../../web/core/mesh';
import {
  exportMesh,
  meshFacts,
  parseForView,
  parseMesh,
  predictSize,
  subdivide,
  subdivideForView,
  viewMesh,
} from '../../web/core/subdiv-core';
import { SubdivError } from '../../web/core/subdiv-error';
import { fanPolygons } from '../../web/render/fan-polygons';
import { loadFixture } from './test-helpers';

beforeAll(async () => {
  await initNode();
});

function edgeSet(edges: Uint32Array): Set<string> {
  const set = new Set<string>();
  for (let i = 0; i < edges.length; i += 2) set.add(`${edges[i]}-${edges[i + 1]}`);
  return set;
}

describe('render buffers from the core', () => {
  it('draws the cube as 12 triangles and 12 edges, no diagonals', () => {
    const cube = loadFixture('cube.off');
    const r = viewMesh(cube).buffers;
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
    // The cube spans [-1, 1]³: the sphere three.js would compute, centred at 0 with radius √3.
    expect(Array.from(r.boundingSphere.subarray(0, 3))).toEqual([0, 0, 0]);
    expect(r.boundingSphere[3]).toBeCloseTo(Math.sqrt(3), 5);
    expect(r.boundingSphere[3]).toBeGreaterThanOrEqual(Math.fround(Math.sqrt(3)));
    // Each corner of the cube: its normal points away from the centre, into its octant.
    for (let v = 0; v < 8; v++) {
      for (let k = 0; k < 3; k++) expect(Math.sign(r.normals[3 * v + k])).toBe(Math.sign(cube.positions[3 * v + k]));
      expect(Math.hypot(r.normals[3 * v], r.normals[3 * v + 1], r.normals[3 * v + 2])).toBeCloseTo(1, 6);
    }
  });

  it('fans each polygon from its first corner, keeping its orientation', () => {
    const pentagon: Mesh = {
      positions: new Float64Array([1, 0, 0, 0.3, 0.95, 0, -0.8, 0.6, 0, -0.8, -0.6, 0, 0.3, -0.95, 0]),
      faceSizes: new Uint32Array([5]),
      faceIndices: new Uint32Array([0, 1, 2, 3, 4]),
      controlEdges: new Uint32Array(0),
    };
    const r = viewMesh(pentagon).buffers;
    expect(Array.from(r.triangles)).toEqual([0, 1, 2, 0, 2, 3, 0, 3, 4]);
    expect(Array.from(r.triangleFace)).toEqual([0, 0, 0]);
    // Edges by their smaller vertex, then in the order they appear.
    expect(Array.from(r.edges)).toEqual([0, 1, 0, 4, 1, 2, 2, 3, 3, 4]);
    // Counter-clockwise seen from +z: every normal is +z.
    expect(Array.from(r.normals)).toEqual([0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1]);
  });

  it('lists the border: the 12 outer edges of the open 3 × 3 grid, 4·2·3 = 24 at Catmull-Clark level 1, none on the torus', () => {
    const grid = loadFixture('grid-open.off');
    const r = viewMesh(grid).buffers;
    expect(r.borderEdges.length / 2).toBe(12);
    const edges = edgeSet(r.edges);
    for (const e of edgeSet(r.borderEdges)) expect(edges.has(e)).toBe(true);
    // Each border edge joins two border-row or border-column vertices of the 4 × 4 grid.
    const onRim = (v: number) => v % 4 === 0 || v % 4 === 3 || v < 4 || v >= 12;
    for (const v of r.borderEdges) expect(onRim(v)).toBe(true);
    expect(viewMesh(subdivide(grid, { scheme: 'catmull-clark', levels: 1 })).buffers.borderEdges.length / 2).toBe(24);
    expect(viewMesh(loadFixture('torus-quad.off')).buffers.borderEdges.length).toBe(0);
  });

  it.each(['mixed-open.off', 'torus-quad.off', 'rhombicuboctahedron.off'])(
    'on %s and its Catmull-Clark level 2: edges = the facts edges, triangles = Σ(degree - 2)',
    (fixture) => {
      const base = loadFixture(fixture);
      for (const mesh of [base, subdivide(base, { scheme: 'catmull-clark', levels: 2 })]) {
        const r = viewMesh(mesh).buffers;
        const facts = meshFacts(mesh);
        expect(r.edges.length / 2).toBe(facts.edges);
        expect(edgeSet(r.edges).size).toBe(facts.edges);
        const expectedTriangles = Array.from(mesh.faceSizes).reduce((s, k) => s + k - 2, 0);
        expect(r.triangles.length / 3).toBe(expectedTriangles);
        expect(Math.max(...r.triangles)).toBeLessThan(facts.vertices);
        expect(r.normals.length).toBe(3 * facts.vertices);
      }
    },
  );
});

describe('fanPolygons', () => {
  it.each(['mixed-open.off', 'rhombicuboctahedron.off', 'cube.off'])(
    'gives back the polygons of %s from its fan triangles, corner for corner',
    (fixture) => {
      const mesh = loadFixture(fixture);
      const polygons = fanPolygons(viewMesh(mesh).buffers);
      expect(polygons.faceSizes).toEqual(mesh.faceSizes);
      expect(polygons.faceIndices).toEqual(mesh.faceIndices);
    },
  );

  it('gives nothing for no triangles', () => {
    const empty = {
      positions: new Float32Array(0),
      boundingSphere: new Float32Array(4),
      normals: new Float32Array(0),
      triangles: new Uint32Array(0),
    };
    const polygons = fanPolygons({
      ...empty,
      edges: new Uint32Array(0),
      triangleFace: new Uint32Array(0),
      borderEdges: new Uint32Array(0),
    });
    expect(polygons.faceSizes.length).toBe(0);
    expect(polygons.faceIndices.length).toBe(0);
  });
});

describe('parseForView', () => {
  it.each(['mixed-open.off', 'torus-quad.off', 'cube.obj'])(
    '%s: the mesh, facts and buffers of parseMesh then viewMesh',
    (fixture) => {
      const mesh = loadFixture(fixture);
      const format = fixture.endsWith('.obj') ? 'obj' : 'off';
      const text = exportMesh(mesh, format);
      const once = parseForView(text, format);
      const twice = viewMesh(parseMesh(text, format));
      expect(once.mesh).toEqual(twice.mesh);
      expect(once.facts).toEqual(twice.facts);
      expect(once.buffers).toEqual(twice.buffers);
    },
  );

  it('refuses what parseMesh refuses, with its line', () => {
    const bad = 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n';
    expect(() => parseForView(bad, 'off')).toThrow(SubdivError);
    let line = 0;
    try {
      parseForView(bad, 'off');
    } catch (e) {
      line = (e as SubdivError).line;
    }
    expect(line).toBe(6);
  });
});

describe('subdivideForView', () => {
  const schemes: SchemeName[] = ['catmull-clark', 'loop', 'doo-sabin', 'sqrt3', 'quad-triangle', 'linear'];
  it.each(schemes)('%s on the open mixed mesh: the same mesh as subdivide, facts as computed afresh', (scheme) => {
    let mesh = loadFixture('mixed-open.off');
    let facts = meshFacts(mesh);
    for (let level = 1; level <= 2; level++) {
      const options = { scheme, levels: 1, startLevel: level - 1, triangulate: true };
      const view = subdivideForView(mesh, options, facts);
      const plain = subdivide(mesh, options);
      expect(view.mesh.positions).toEqual(plain.positions);
      expect(view.mesh.faceIndices).toEqual(plain.faceIndices);
      expect(view.facts).toEqual(meshFacts(plain));
      expect(view.buffers.edges.length / 2).toBe(view.facts.edges);
      mesh = view.mesh;
      facts = view.facts;
    }
  });

  it('counts the render buffers in the prediction and fails as subdivide does', () => {
    const torus = loadFixture('torus-tri.off');
    const plain = predictSize(torus, { scheme: 'loop', levels: 1 });
    const viewed = predictSize(torus, { scheme: 'loop', levels: 1, renderBuffers: true });
    expect(viewed.faces).toBe(plain.faces);
    expect(viewed.peakBytes).toBeGreaterThan(plain.peakBytes);
    const cube = loadFixture('cube.off');
    expect(() => subdivideForView(cube, { scheme: 'loop', levels: 1 }, meshFacts(cube))).toThrow(SubdivError);
    expect(() => subdivideForView(cube, { scheme: 'loop', levels: 1 }, meshFacts(cube))).toThrow(
      /loop needs a triangle mesh/,
    );
  });
});
