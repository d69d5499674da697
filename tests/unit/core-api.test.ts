/** The TypeScript API over the WASM core: init, round trips, facts, names. */
import { beforeAll, describe, expect, it } from 'vitest';
import { initNode } from '../../web/core/init-node';
import type { MeshFormat, SchemeName } from '../../web/core/mesh';
import {
  exportMesh,
  formatFromFileName,
  heapBytesInUse,
  init,
  isReady,
  meshFacts,
  parseMesh,
  predictSize,
  predictSizeOfLevel,
  schemeNames,
  subdivide,
} from '../../web/core/subdiv-core';
import { expectCounts, expectSamePoints, fixtureText, loadFixture, rulePreset } from './test-helpers';

beforeAll(async () => {
  await initNode();
});

const FIXTURES = [
  'cube.off',
  'cube.obj',
  'tetrahedron.off',
  'octahedron.off',
  'icosahedron.off',
  'torus-quad.off',
  'torus-tri.off',
  'grid-open.off',
  'disk-tri.off',
  'mixed-open.off',
  'rhombicuboctahedron.off',
  'two-tetrahedra.off',
];

describe('init', () => {
  it('is idempotent: later calls resolve at once and keep the same instance', async () => {
    expect(isReady()).toBe(true);
    const before = heapBytesInUse();
    await Promise.all([init(), init({ wasmBinary: new Uint8Array(0) }), initNode()]);
    expect(isReady()).toBe(true);
    expect(heapBytesInUse()).toBe(before);
  });

  it('names the four schemes in display order', () => {
    expect(schemeNames().slice(0, 4)).toEqual(['catmull-clark', 'loop', 'doo-sabin', 'sqrt3']);
  });
});

describe('round trips', () => {
  const cases = FIXTURES.flatMap((name) => (['off', 'obj'] as MeshFormat[]).map((f) => [name, f] as const));
  it.each(cases)('%s through %s: same counts and coordinates', (name, format) => {
    const mesh = loadFixture(name);
    const text = exportMesh(mesh, format);
    const back = parseMesh(text, format);
    expect(Array.from(back.faceSizes)).toEqual(Array.from(mesh.faceSizes));
    expect(Array.from(back.faceIndices)).toEqual(Array.from(mesh.faceIndices));
    expectSamePoints(back, mesh, 1e-12);
  });

  it('keeps subdivided coordinates (17 significant digits) through OFF and OBJ', () => {
    const mesh = subdivide(loadFixture('icosahedron.off'), { scheme: 'loop', levels: 2 });
    for (const format of ['off', 'obj'] as const) {
      const back = parseMesh(exportMesh(mesh, format), format);
      expectSamePoints(back, mesh, 0);
      expect(back.faceIndices.length).toBe(mesh.faceIndices.length);
    }
  });

  it('returns plain typed arrays that survive heap growth', () => {
    const small = loadFixture('cube.off');
    const copy = Float64Array.from(small.positions);
    // A big step grows the WASM memory; arrays handed out before must not detach.
    subdivide(loadFixture('torus-quad.off'), { scheme: 'catmull-clark', levels: 5 });
    expect(small.positions).toBeInstanceOf(Float64Array);
    expect(small.faceSizes).toBeInstanceOf(Uint32Array);
    expect(small.faceIndices).toBeInstanceOf(Uint32Array);
    expect(small.controlEdges).toBeInstanceOf(Uint32Array);
    expect(Array.from(small.positions)).toEqual(Array.from(copy));
  });

  it('accepts plain arrays as input buffers too', () => {
    const cube = loadFixture('cube.off');
    const loose = {
      positions: Array.from(cube.positions),
      faceSizes: Array.from(cube.faceSizes),
      faceIndices: Array.from(cube.faceIndices),
      controlEdges: [],
    } as unknown as typeof cube;
    expectCounts(meshFacts(loose), { vertices: 8, edges: 12, faces: 6 });
  });
});

describe('facts', () => {
  it('of the fixtures: counts, components, boundaries, genus, face kinds, bounding box', () => {
    expect(meshFacts(loadFixture('cube.off'))).toEqual({
      vertices: 8,
      edges: 12,
      faces: 6,
      components: 1,
      boundaries: 0,
      eulerCharacteristic: 2,
      genus: 0,
      closed: true,
      triangles: 0,
      quads: 6,
      otherFaces: 0,
      bboxMin: [-1, -1, -1],
      bboxMax: [1, 1, 1],
      controlEdges: 0,
    });
    expectCounts(meshFacts(loadFixture('torus-quad.off')), {
      vertices: 48,
      edges: 96,
      faces: 48,
      eulerCharacteristic: 0,
      genus: 1,
      closed: true,
    });
    expectCounts(meshFacts(loadFixture('mixed-open.off')), {
      vertices: 13,
      faces: 9,
      components: 1,
      boundaries: 1,
      closed: false,
      triangles: 6,
      quads: 2,
      otherFaces: 1,
      genus: 0,
    });
    expectCounts(meshFacts(loadFixture('two-tetrahedra.off')), {
      components: 2,
      eulerCharacteristic: 4,
      genus: 0,
    });
  });

  it('the OBJ cube (with vt/vn and extra statements) equals the OFF cube', () => {
    const obj = parseMesh(fixtureText('cube.obj'), 'obj');
    expectCounts(meshFacts(obj), { vertices: 8, edges: 12, faces: 6, quads: 6, genus: 0 });
  });
});

describe('predictSize', () => {
  it('predicts the counts subdivide gives', () => {
    const torus = loadFixture('torus-quad.off');
    for (const levels of [1, 2, 3]) {
      const p = predictSize(torus, { scheme: 'catmull-clark', levels });
      const f = meshFacts(subdivide(torus, { scheme: 'catmull-clark', levels }));
      expect([p.vertices, p.edges, p.faces]).toEqual([f.vertices, f.edges, f.faces]);
      expect(p.peakBytes).toBeGreaterThan(0);
    }
    // Without a limit, the step is checked against what the 4 GB heap can still take.
    const limit = predictSize(torus, { scheme: 'catmull-clark', levels: 1 }).memoryLimitBytes ?? 0;
    expect(limit).toBeGreaterThan(3 * 2 ** 30);
    expect(limit).toBeLessThan(4 * 2 ** 30 - heapBytesInUse());
    expect(predictSize(torus, { scheme: 'catmull-clark', levels: 1, memoryLimitBytes: 12345 }).memoryLimitBytes).toBe(
      12345,
    );
    const ico = loadFixture('icosahedron.off');
    const p = predictSize(ico, { scheme: 'loop', levels: 4 });
    expect(p.faces).toBe(20 * 4 ** 4);
  });

  it('predicts the next step of a closed level from its facts, with the figures of its arrays', () => {
    const rules = rulePreset('sqrt3');
    for (const [fixture, options] of [
      ['cube.off', { scheme: 'catmull-clark' }],
      ['icosahedron.off', { scheme: 'loop' }],
      ['torus-quad.off', { scheme: 'doo-sabin' }],
      ['octahedron.off', { scheme: 'custom', rules }],
      ['cube.off', { scheme: 'loop', triangulate: true }],
    ] as const) {
      const control = loadFixture(fixture);
      for (const k of [1, 2]) {
        const level = subdivide(control, { ...options, levels: k });
        const next = { ...options, levels: 1, startLevel: k };
        // The memory limit is what the heap can still take, which moves between calls: not compared.
        const { memoryLimitBytes: _a, ...fromFacts } = predictSizeOfLevel(level, meshFacts(level), next);
        const { memoryLimitBytes: _b, ...fromArrays } = predictSize(level, next);
        expect(fromFacts, `${fixture} ${options.scheme} level ${k}`).toEqual(fromArrays);
      }
    }
    // It reads the facts, not the arrays: the cube's arrays with a torus's facts give the torus's figures.
    const torus = loadFixture('torus-quad.off');
    const cube = loadFixture('cube.off');
    const cc = { scheme: 'catmull-clark', levels: 1, memoryLimitBytes: 2 ** 30 } as const;
    expect(predictSizeOfLevel(cube, meshFacts(torus), cc)).toEqual(predictSize(torus, cc));
    // An open level goes through its arrays (facts that say otherwise are not read).
    const grid = loadFixture('grid-open.off');
    expect(predictSizeOfLevel(grid, { ...meshFacts(grid), vertices: 10 ** 6 }, cc)).toEqual(predictSize(grid, cc));
  });
});

describe("CGAL's hosts (option cgalHosts)", () => {
  const RUNS: [string, SchemeName][] = [
    ['torus-quad.off', 'catmull-clark'],
    ['grid-open.off', 'catmull-clark'],
    ['torus-tri.off', 'loop'],
    ['disk-tri.off', 'loop'],
    ['torus-quad.off', 'doo-sabin'],
    ['grid-open.off', 'doo-sabin'],
    ['torus-tri.off', 'sqrt3'],
    ['mixed-open.off', 'quad-triangle'],
  ];
  it.each(RUNS)('%s, %s x2: the same mesh as the fast hosts, index for index', (name, scheme) => {
    const mesh = loadFixture(name);
    const fast = subdivide(mesh, { scheme, levels: 2 });
    const cgal = subdivide(mesh, { scheme, levels: 2, cgalHosts: true });
    expect(Array.from(cgal.faceSizes)).toEqual(Array.from(fast.faceSizes));
    expect(Array.from(cgal.faceIndices)).toEqual(Array.from(fast.faceIndices));
    // The same control edges, listed in another order.
    const pairs = (edges: Uint32Array) =>
      Array.from({ length: edges.length / 2 }, (_, i) => `${edges[2 * i]} ${edges[2 * i + 1]}`).sort();
    expect(pairs(cgal.controlEdges)).toEqual(pairs(fast.controlEdges));
    expectSamePoints(cgal, fast);
  });

  it('are predicted larger than the fast hosts, with the same counts', () => {
    const mesh = loadFixture('torus-quad.off');
    const fast = predictSize(mesh, { scheme: 'catmull-clark', levels: 3 });
    const cgal = predictSize(mesh, { scheme: 'catmull-clark', levels: 3, cgalHosts: true });
    expect([cgal.vertices, cgal.edges, cgal.faces]).toEqual([fast.vertices, fast.edges, fast.faces]);
    expect(cgal.peakBytes).toBeGreaterThan(2 * fast.peakBytes);
  });
});

describe('formatFromFileName', () => {
  it('reads the extension in any case', () => {
    expect(formatFromFileName('bunny.OFF')).toBe('off');
    expect(formatFromFileName('dir/x.obj')).toBe('obj');
    expect(formatFromFileName('scan.PLY')).toBe('ply');
    expect(formatFromFileName('part.stl')).toBe('stl');
    expect(formatFromFileName('mesh.fbx')).toBeNull();
    expect(formatFromFileName('off')).toBeNull();
  });
});
