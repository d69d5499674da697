/**
 * `subdiv halfedges` and halfedgeTable through the real WASM core: the
 * table's invariants, checked here on the JSON a student would read
 * (opposite is h xor 1 and an involution, prev is next's inverse, following
 * next from a face's halfedge visits its corners in the file's order, the
 * border halfedges form the facts' boundary loops), and its failures.
 */
import { spawnSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { beforeAll, describe, expect, it } from 'vitest';
import { initNode } from '../../web/core/init-node';
import type { Mesh } from '../../web/core/mesh';
import {
  compareMeshes,
  eulerOperator,
  halfedgeTable,
  meshFacts,
  parseMesh,
  sqrt3ByHand,
  subdivide,
} from '../../web/core/subdiv-core';
import { SubdivError } from '../../web/core/subdiv-error';
import { FIXTURES_DIR, loadFixture, toPlain } from './test-helpers';

const BIN = join(dirname(fileURLToPath(import.meta.url)), '..', '..', 'bin', 'subdiv.mjs');

beforeAll(async () => {
  await initNode();
});

interface Row {
  h: number;
  next: number;
  prev: number;
  opposite: number;
  vertex: number;
  face: number | null;
}

function halfedgesCli(args: string[]): { status: number | null; stdout: string; stderr: string } {
  return spawnSync(process.execPath, [BIN, 'halfedges', ...args], { encoding: 'utf8' });
}

/** The invariants of the table `rows` of `mesh`; returns the number of border loops. */
function expectValid(rows: Row[], mesh: Mesh): number {
  const { faces } = toPlain(mesh);
  expect(rows.length).toBe(2 * meshFacts(mesh).edges);
  rows.forEach((r, h) => {
    expect(r.h).toBe(h);
    expect(r.opposite).toBe(h ^ 1);
    expect(rows[r.opposite].opposite).toBe(h);
    expect(rows[r.next].prev).toBe(h);
    // h runs from its opposite's vertex to its own: its previous one ends where it starts.
    expect(rows[r.prev].vertex).toBe(rows[r.opposite].vertex);
  });
  faces.forEach((corners, f) => {
    const start = rows.find((r) => r.face === f && r.vertex === corners[0]);
    expect(start, `face ${f}`).toBeDefined();
    let h = start?.h ?? -1;
    for (const corner of corners) {
      expect(rows[h]).toMatchObject({ face: f, vertex: corner });
      h = rows[h].next;
    }
    expect(h).toBe(start?.h);
  });
  const seen = new Set<number>();
  let loops = 0;
  for (const r of rows) {
    if (r.face !== null || seen.has(r.h)) continue;
    loops++;
    for (let h = r.h; !seen.has(h); h = rows[h].next) {
      expect(rows[h].face).toBeNull();
      seen.add(h);
    }
  }
  return loops;
}

describe('subdiv halfedges', () => {
  it('prints the 24 halfedges of the cube, none on the border, one per line', () => {
    const r = halfedgesCli([join(FIXTURES_DIR, 'cube.off')]);
    expect(r.status).toBe(0);
    const out = JSON.parse(r.stdout);
    expect(out).toMatchObject({ vertices: 8, faces: 6, halfedges: 24, borderHalfedges: 0 });
    expect(r.stdout.split('\n').filter((line) => line.trimStart().startsWith('{"h":'))).toHaveLength(24);
    expect(expectValid(out.table, loadFixture('cube.off'))).toBe(0);
  });

  it('level 1 of the open grid under Catmull-Clark: 84 edges, one border loop of 24', () => {
    const r = halfedgesCli([join(FIXTURES_DIR, 'grid-open.off'), '--levels', '1']);
    expect(r.status).toBe(0);
    const out = JSON.parse(r.stdout);
    expect(out).toMatchObject({
      scheme: 'catmull-clark',
      levels: 1,
      vertices: 49,
      faces: 36,
      halfedges: 168,
      borderHalfedges: 24,
    });
    const level = subdivide(loadFixture('grid-open.off'), { scheme: 'catmull-clark', levels: 1 });
    expect(expectValid(out.table, level)).toBe(1);
  });

  it('on levels 1 and 2 of every scheme of a mixed open mesh the invariants hold', () => {
    const control = loadFixture('mixed-open.off');
    for (const scheme of ['catmull-clark', 'loop', 'doo-sabin', 'sqrt3', 'quad-triangle', 'linear'] as const) {
      for (const levels of [1, 2]) {
        const mesh = subdivide(control, { scheme, levels, triangulate: true });
        const t = halfedgeTable(mesh);
        const rows: Row[] = Array.from(t.next, (next, h) => ({
          h,
          next,
          prev: t.prev[h],
          opposite: t.opposite[h],
          vertex: t.target[h],
          face: t.face[h] < 0 ? null : t.face[h],
        }));
        expect(expectValid(rows, mesh), `${scheme} ${levels}`).toBe(meshFacts(mesh).boundaries);
      }
    }
  });

  it('a file that is not a valid mesh: one error line naming it and the problem, exit 1', () => {
    const r = halfedgesCli([join(FIXTURES_DIR, 'invalid', 'non-manifold-edge.off')]);
    expect(r.status).toBe(1);
    expect(r.stdout).toBe('');
    expect(r.stderr).toMatch(/^error: .*non-manifold-edge\.off: .+/);
  });

  it('halfedgeTable refuses buffers that are not a valid mesh with a SubdivError', () => {
    const twice: Mesh = parseMesh(readFileSync(join(FIXTURES_DIR, 'tetrahedron.off'), 'utf8'), 'off');
    const broken: Mesh = {
      ...twice,
      faceSizes: Uint32Array.of(3, 3),
      faceIndices: Uint32Array.of(0, 1, 2, 0, 1, 2),
    };
    expect(() => halfedgeTable(broken)).toThrow(SubdivError);
  });
});

describe('Euler operators through the WASM core', () => {
  it('split_face on the cube: 7 faces, χ = 2, CGAL valid; join_face across the new edge gives the cube back', () => {
    const cube = loadFixture('cube.off');
    const t = halfedgeTable(cube);
    const split = eulerOperator(cube, 'split_face', 0, t.next[t.next[0]]);
    expect(split.valid).toBe(true);
    expect(split.facts).toMatchObject({ vertices: 8, edges: 13, faces: 7, eulerCharacteristic: 2, triangles: 2 });
    const joined = eulerOperator(split.mesh, 'join_face', split.halfedge);
    expect(compareMeshes(cube, joined.mesh, 1e-12)).toMatchObject({ match: true, sameFaces: true });
  });

  it('a broken precondition is a SubdivError naming it', () => {
    const cube = loadFixture('cube.off');
    expect(() => eulerOperator(cube, 'flip_edge', 0)).toThrow('only an edge between two triangles can be flipped');
    expect(() => eulerOperator(cube, 'split_edge', 99)).toThrow('halfedge 99 does not exist (24 halfedges)');
  });

  it('√3 by hand on the icosahedron: 20 + 30 + 12 operators, ending at level 1 of the √3 scheme', () => {
    const ico = loadFixture('icosahedron.off');
    const walk = sqrt3ByHand(ico);
    expect(walk).toMatchObject({ done: 62, total: 62, last: 'smooth vertex 11, valence 5' });
    const scheme = subdivide(ico, { scheme: 'sqrt3', levels: 1 });
    expect(compareMeshes(scheme, walk.mesh, 1e-12)).toMatchObject({ match: true, sameFaces: true });
    const centres = sqrt3ByHand(ico, 20);
    expect(centres.last).toBe('add_center_vertex (face 19)');
    expect(meshFacts(centres.mesh)).toMatchObject({ vertices: 32, faces: 60 });
  });
});
