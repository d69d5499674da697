/** Each scheme through the WASM core: exact counts, invariants, and points against the published rules. */
import { beforeAll, describe, expect, it } from 'vitest';
import { initNode } from '../../web/core/init-node';
import type { CgalSchemeName, Mesh, MeshFacts, SchemeName } from '../../web/core/mesh';
import type { RuleHost } from '../../web/core/rule-set';
import { SCHEME_TABLE } from '../../web/core/scheme-table';
import { coreSchemeInfo, hostOf, meshFacts, schemeNames, subdivide } from '../../web/core/subdiv-core';
import { SubdivError } from '../../web/core/subdiv-error';
import { hostLabel, hostNeedsTriangles, SCHEME_NAMES, schemeInfo } from '../../web/viewer/scheme-info';
import { catmullClarkStep, loopStep, repeat } from './reference-subdivision';
import { expectCounts, expectSameMesh, expectSamePoints, loadFixture, toPlain } from './test-helpers';

beforeAll(async () => {
  await initNode();
});

interface Counts {
  vertices: number;
  edges: number;
  faces: number;
  /** Sum of face degrees. */
  corners: number;
}

function countsOf(mesh: Mesh): Counts {
  const f = meshFacts(mesh);
  return { vertices: f.vertices, edges: f.edges, faces: f.faces, corners: mesh.faceIndices.length };
}

/** One step's counts on a closed mesh, from the scheme's connectivity rule. */
const closedStep: Record<CgalSchemeName, (c: Counts) => Counts> = {
  // Catmull-Clark: every corner of every face becomes a quad.
  'catmull-clark': (c) => ({
    vertices: c.vertices + c.edges + c.faces,
    edges: 2 * c.edges + c.corners,
    faces: c.corners,
    corners: 4 * c.corners,
  }),
  // Loop: 1 -> 4 triangles.
  loop: (c) => ({
    vertices: c.vertices + c.edges,
    edges: 2 * c.edges + 3 * c.faces,
    faces: 4 * c.faces,
    corners: 12 * c.faces,
  }),
  // √3: a vertex per face, 3 triangles per face, old edges flipped.
  sqrt3: (c) => ({
    vertices: c.vertices + c.faces,
    edges: c.edges + 3 * c.faces,
    faces: 3 * c.faces,
    corners: 9 * c.faces,
  }),
  // Doo-Sabin: a face per face, per edge (quad) and per vertex; a vertex per corner.
  'doo-sabin': (c) => ({
    vertices: c.corners,
    edges: 2 * c.corners,
    faces: c.vertices + c.edges + c.faces,
    corners: 4 * c.corners,
  }),
};

const closedCases: [CgalSchemeName, string][] = [
  ['catmull-clark', 'cube.off'],
  ['catmull-clark', 'torus-quad.off'],
  ['catmull-clark', 'rhombicuboctahedron.off'],
  ['catmull-clark', 'tetrahedron.off'],
  ['loop', 'tetrahedron.off'],
  ['loop', 'icosahedron.off'],
  ['loop', 'torus-tri.off'],
  ['loop', 'two-tetrahedra.off'],
  ['sqrt3', 'octahedron.off'],
  ['sqrt3', 'torus-tri.off'],
  ['doo-sabin', 'cube.off'],
  ['doo-sabin', 'torus-quad.off'],
  ['doo-sabin', 'rhombicuboctahedron.off'],
  ['doo-sabin', 'icosahedron.off'],
];

const invariants = (f: MeshFacts) => ({
  components: f.components,
  boundaries: f.boundaries,
  genus: f.genus,
  closed: f.closed,
});

describe('closed meshes: exact counts at levels 1-3, topology preserved', () => {
  it.each(closedCases)('%s on %s', (scheme, fixture) => {
    const mesh = loadFixture(fixture);
    const before = meshFacts(mesh);
    let expected = countsOf(mesh);
    for (let levels = 1; levels <= 3; levels++) {
      expected = closedStep[scheme](expected);
      const out = subdivide(mesh, { scheme, levels });
      expect(countsOf(out)).toEqual(expected);
      expect(invariants(meshFacts(out))).toEqual(invariants(before));
    }
  });

  it('gives the closed formulas on the cube as literal numbers', () => {
    const cube = loadFixture('cube.off');
    expectCounts(meshFacts(subdivide(cube, { scheme: 'catmull-clark', levels: 3 })), {
      vertices: 386,
      edges: 768,
      faces: 384,
      quads: 384,
      genus: 0,
    });
    expectCounts(meshFacts(subdivide(cube, { scheme: 'doo-sabin', levels: 1 })), {
      vertices: 24,
      edges: 48,
      faces: 26,
      quads: 18,
      triangles: 8,
    });
    const octahedron = loadFixture('octahedron.off');
    expectCounts(meshFacts(subdivide(octahedron, { scheme: 'sqrt3', levels: 2 })), {
      vertices: 6 + 8 + 24,
      faces: 72,
      triangles: 72,
    });
    expectCounts(meshFacts(subdivide(octahedron, { scheme: 'loop', levels: 2 })), { faces: 128, vertices: 66 });
  });
});

describe('open meshes: borders and topology kept by every scheme', () => {
  const openCases: [SchemeName, string][] = [
    ['catmull-clark', 'grid-open.off'],
    ['catmull-clark', 'mixed-open.off'],
    ['catmull-clark', 'disk-tri.off'],
    ['loop', 'disk-tri.off'],
    ['sqrt3', 'disk-tri.off'],
    ['doo-sabin', 'grid-open.off'],
    ['doo-sabin', 'mixed-open.off'],
    ['doo-sabin', 'disk-tri.off'],
  ];
  it.each(openCases)('%s on %s', (scheme, fixture) => {
    const mesh = loadFixture(fixture);
    const before = meshFacts(mesh);
    expect(before.closed).toBe(false);
    for (let levels = 1; levels <= 3; levels++) {
      const after = meshFacts(subdivide(mesh, { scheme, levels }));
      expect(invariants(after)).toEqual(invariants(before));
      expect(after.faces).toBeGreaterThan(before.faces);
    }
  });

  it('Catmull-Clark and Loop counts on open meshes follow the same split rules', () => {
    const grid = loadFixture('grid-open.off');
    let c = countsOf(grid);
    for (let levels = 1; levels <= 3; levels++) {
      c = closedStep['catmull-clark'](c);
      expect(countsOf(subdivide(grid, { scheme: 'catmull-clark', levels }))).toEqual(c);
    }
    const disk = loadFixture('disk-tri.off');
    let d = countsOf(disk);
    for (let levels = 1; levels <= 3; levels++) {
      d = closedStep.loop(d);
      expect(countsOf(subdivide(disk, { scheme: 'loop', levels }))).toEqual(d);
    }
  });

  it('Doo-Sabin on an open grid keeps its border inside the control border', () => {
    const grid = loadFixture('grid-open.off');
    const out = subdivide(grid, { scheme: 'doo-sabin', levels: 2 });
    const facts = meshFacts(out);
    expect(facts.boundaries).toBe(1);
    expect(facts.bboxMin[0]).toBeGreaterThanOrEqual(0);
    expect(facts.bboxMax[0]).toBeLessThanOrEqual(3);
    expect(Math.abs(facts.bboxMin[2])).toBe(0);
    expect(Math.abs(facts.bboxMax[2])).toBe(0);
  });
});

describe('points against the published rules (plain implementation in the tests)', () => {
  it.each([
    'cube.off',
    'torus-quad.off',
    'rhombicuboctahedron.off',
    'tetrahedron.off',
    'grid-open.off',
    'mixed-open.off',
  ])('Catmull-Clark on %s, levels 1-3', (fixture) => {
    const mesh = loadFixture(fixture);
    for (let levels = 1; levels <= 3; levels++) {
      const expected = repeat(catmullClarkStep, toPlain(mesh), levels);
      expectSameMesh(subdivide(mesh, { scheme: 'catmull-clark', levels }), expected);
    }
  });

  it.each(['tetrahedron.off', 'icosahedron.off', 'torus-tri.off', 'disk-tri.off', 'octahedron.off'])(
    'Loop on %s, levels 1-3',
    (fixture) => {
      const mesh = loadFixture(fixture);
      for (let levels = 1; levels <= 3; levels++) {
        const expected = repeat(loopStep, toPlain(mesh), levels);
        expectSameMesh(subdivide(mesh, { scheme: 'loop', levels }), expected);
      }
    },
  );

  it('a cube corner goes where the Catmull-Clark vertex rule puts it, (5/9, 5/9, 5/9)', () => {
    // Corner S = (1,1,1) of [-1,1]^3, n = 3: Q = mean of the face centres (1,0,0), (0,1,0),
    // (0,0,1) = (1/3)·1; R = mean of the edge midpoints (1,1,0), ... = (2/3)·1;
    // (Q + 2R + (n-3)S) / n = (1/3 + 4/3) / 3 = 5/9.
    const out = toPlain(subdivide(loadFixture('cube.off'), { scheme: 'catmull-clark', levels: 1 }));
    const corner = out.points.find((p) => p.every((x) => x > 0.5));
    expect(corner).toBeDefined();
    for (const x of corner ?? []) expect(x).toBeCloseTo(5 / 9, 14);
  });
});

describe('levels and options', () => {
  it('levels 0 returns the mesh unchanged', () => {
    const mesh = loadFixture('mixed-open.off');
    const out = subdivide(mesh, { scheme: 'catmull-clark', levels: 0 });
    expect(Array.from(out.faceSizes)).toEqual(Array.from(mesh.faceSizes));
    expect(Array.from(out.faceIndices)).toEqual(Array.from(mesh.faceIndices));
    expectSamePoints(out, mesh, 0);
  });

  it('does not change its input', () => {
    const mesh = loadFixture('cube.off');
    const copy = Float64Array.from(mesh.positions);
    subdivide(mesh, { scheme: 'catmull-clark', levels: 2 });
    expect(Array.from(mesh.positions)).toEqual(Array.from(copy));
  });

  it('√3 on an open mesh: two single steps equal one call of two levels', () => {
    const disk = loadFixture('disk-tri.off');
    for (const total of [2, 3]) {
      const once = subdivide(disk, { scheme: 'sqrt3', levels: total });
      let stepped = disk;
      for (let level = 0; level < total; level++) {
        stepped = subdivide(stepped, { scheme: 'sqrt3', levels: 1, startLevel: level });
      }
      expectSameMesh(stepped, toPlain(once));
    }
  });

  it.each(['loop', 'sqrt3'] as const)('%s refuses quads unless asked to triangulate', (scheme) => {
    const cube = loadFixture('cube.off');
    let error: unknown;
    try {
      subdivide(cube, { scheme, levels: 1 });
    } catch (e) {
      error = e;
    }
    expect(error).toBeInstanceOf(SubdivError);
    expect((error as SubdivError).code).toBe('not_triangles');
    expect((error as SubdivError).message).toContain(scheme);
    expect((error as SubdivError).message).toMatch(/\b6\b/);
    const out = meshFacts(subdivide(cube, { scheme, levels: 1, triangulate: true }));
    expect(out.faces).toBe(scheme === 'loop' ? 48 : 36);
    expect(out.genus).toBe(0);
  });

  it('rejects an unknown scheme and negative levels with invalid_argument', () => {
    const cube = loadFixture('cube.off');
    expect(() => subdivide(cube, { scheme: 'butterfly' as SchemeName, levels: 1 })).toThrowError(
      expect.objectContaining({ code: 'invalid_argument' }),
    );
    expect(() => subdivide(cube, { scheme: 'loop', levels: -1 })).toThrowError(
      expect.objectContaining({ code: 'invalid_argument' }),
    );
    expect(() => subdivide(cube, { scheme: 'loop', levels: 1.5 })).toThrowError(
      expect.objectContaining({ code: 'invalid_argument' }),
    );
  });
});

describe("the core's scheme table", () => {
  it('names every scheme in order, with its host, and each host what it needs', () => {
    const { hosts, schemes } = coreSchemeInfo();
    expect(schemes.map((s) => s.name)).toEqual(schemeNames());
    expect(schemes.map((s) => [s.name, s.host])).toEqual([
      ['catmull-clark', 'pqq'],
      ['loop', 'ptq'],
      ['doo-sabin', 'dqq'],
      ['sqrt3', 'sqrt3'],
      ['quad-triangle', 'pqt'],
      ['linear', 'pqq'],
      ['linear-tri', 'ptq'],
      ['custom', null],
    ]);
    expect(hosts.map((h) => [h.name, h.needsTriangles, h.keepsControlEdges, h.fast, h.sizeModel])).toEqual([
      ['pqq', false, true, true, 'catmull-clark'],
      ['ptq', true, true, true, 'loop'],
      ['dqq', false, false, true, 'doo-sabin'],
      ['sqrt3', true, false, true, 'sqrt3'],
      ['pqt', false, true, true, 'quad-triangle'],
    ]);
  });

  it('is what the core does: triangles refused where the host needs them, control edges kept where it keeps them', () => {
    const cube = loadFixture('cube.off');
    for (const { name } of coreSchemeInfo().schemes) {
      if (name === 'custom') continue;
      const host = hostOf(name);
      let refused = false;
      try {
        const out = subdivide(cube, { scheme: name as SchemeName, levels: 1 });
        expect(out.controlEdges.length > 0, name).toBe(host?.keepsControlEdges);
      } catch (error) {
        refused = error instanceof SubdivError && error.code === 'not_triangles';
      }
      expect(refused, name).toBe(host?.needsTriangles);
    }
  });

  it("is what the app reads: set-up wrote the module's table for it, and the picker shows it", () => {
    const core = coreSchemeInfo();
    expect(SCHEME_TABLE).toEqual(core);
    expect(SCHEME_NAMES).toEqual(schemeNames());
    const { hosts, schemes } = core;
    for (const s of schemes) {
      const app = schemeInfo(s.name);
      expect(app.label, s.name).toBe(s.label);
      expect(app.description, s.name).toBe(s.description);
      if (s.host) expect(app.needsTriangles, s.name).toBe(hosts.find((h) => h.name === s.host)?.needsTriangles);
      else expect(app.needsRules, s.name).toBe(true);
    }
    expect(schemeInfo('sqrt3').label).toBe('√3 (Kobbelt)');
    expect(schemeInfo('loop').needsTriangles).toBe(true);
    expect(schemeInfo('catmull-clark').needsTriangles).toBe(false);
    for (const h of hosts.filter((x) => x.name !== 'pqt')) {
      expect(hostLabel(h.name as RuleHost)).toBe(h.label);
      expect(hostNeedsTriangles(h.name as RuleHost)).toBe(h.needsTriangles);
    }
    expect(hostLabel('sqrt3')).toBe('√3');
  });
});
