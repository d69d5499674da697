/**
 * The gallery's own samples (public/meshes) load in the core with the
 * counts their notes promise, and the teaching ones have what they are
 * there to show: corners of valence 3 and 5, a mix of polygons, a surface
 * that is open and not planar. Also the per-level table's growth figure.
 */
import { readFileSync } from 'node:fs';
import { beforeAll, describe, expect, it } from 'vitest';
import { SAMPLES } from '../../web/app/samples';
import { initNode } from '../../web/core/init-node';
import { formatFromFileName, meshFacts, parseMesh, subdivide } from '../../web/core/subdiv-core';
import { countText, growthText } from '../../web/ui/level-table';
import { expectCounts, toPlain } from './test-helpers';

beforeAll(async () => {
  await initNode();
});

function sample(id: string) {
  const found = SAMPLES.find((s) => s.id === id);
  if (!found) throw new Error(`no sample ${id}`);
  const format = formatFromFileName(found.path);
  if (!format) throw new Error(`${found.path}: unknown format`);
  return parseMesh(readFileSync(`public/${found.path}`, 'utf8'), format);
}

/** How many vertices have each number of edges. */
function valences(faces: number[][]): Map<number, number> {
  const neighbours = new Map<number, Set<number>>();
  for (const face of faces) {
    face.forEach((a, k) => {
      const b = face[(k + 1) % face.length];
      for (const [p, q] of [
        [a, b],
        [b, a],
      ]) {
        if (!neighbours.has(p)) neighbours.set(p, new Set());
        neighbours.get(p)?.add(q);
      }
    });
  }
  const count = new Map<number, number>();
  for (const set of neighbours.values()) count.set(set.size, (count.get(set.size) ?? 0) + 1);
  return count;
}

describe('the gallery samples', () => {
  it('every sample outside CGAL’s data set is served from public/ and reads as a valid mesh', () => {
    const own = SAMPLES.filter((s) => !s.path.includes('/cgal/'));
    expect(own.length).toBeGreaterThanOrEqual(11);
    for (const s of own) expect(meshFacts(sample(s.id)).faces, s.id).toBeGreaterThan(0);
  });

  it('the rhombic triacontahedron: 30 planar rhombi, 12 corners of valence 5 and 20 of valence 3', () => {
    const mesh = sample('triacontahedron');
    expectCounts(meshFacts(mesh), { vertices: 32, edges: 60, faces: 30, quads: 30, genus: 0, boundaries: 0 });
    const { points, faces } = toPlain(mesh);
    expect(valences(faces)).toEqual(
      new Map([
        [5, 12],
        [3, 20],
      ]),
    );
    // Planar: the two diagonals of each rhombus cross at their midpoints.
    for (const [a, b, c, d] of faces) {
      for (let i = 0; i < 3; i++) expect(points[a][i] + points[c][i]).toBeCloseTo(points[b][i] + points[d][i], 12);
    }
  });

  it('the pentagonal tower: a pentagon, 5 quads and 5 triangles; Catmull-Clark gives a quad per corner', () => {
    const mesh = sample('pentagonal-tower');
    expectCounts(meshFacts(mesh), { vertices: 11, edges: 20, faces: 11, triangles: 5, quads: 5, otherFaces: 1 });
    // Level 1: a vertex per vertex, edge and face (11 + 20 + 11); a quad per corner (5 + 20 + 15).
    expectCounts(meshFacts(subdivide(mesh, { scheme: 'catmull-clark', levels: 1 })), {
      vertices: 42,
      faces: 40,
      quads: 40,
    });
  });

  it('the saddle: 16 quads, open, not planar (z = (x² − y²)/2 from −1/2 to 1/2)', () => {
    const mesh = sample('saddle');
    expectCounts(meshFacts(mesh), { vertices: 25, edges: 40, faces: 16, boundaries: 1, genus: 0 });
    const z = toPlain(mesh).points.map((p) => p[2]);
    expect(Math.min(...z)).toBe(-0.5);
    expect(Math.max(...z)).toBe(0.5);
  });
});

describe('countText', () => {
  it('keeps every digit below a million and gives millions from there', () => {
    expect(countText(0)).toBe('0');
    expect(countText(1920)).toBe('1,920');
    expect(countText(999_999)).toBe('999,999');
    expect(countText(1_000_000)).toBe('1 M');
    expect(countText(4_268_544)).toBe('4.27 M');
    expect(countText(17_074_176)).toBe('17.1 M');
    expect(countText(34_148_352)).toBe('34.1 M');
    expect(countText(273_186_816)).toBe('273.2 M');
    expect(countText(1_092_747_264)).toBe('1,093 M');
  });
});

describe('growthText', () => {
  it('gives the ratio of the faces to two decimals, and a dash where there is no previous level', () => {
    expect(growthText(24, 6)).toBe('×4');
    expect(growthText(26, 6)).toBe('×4.33');
    expect(growthText(98, 26)).toBe('×3.77');
    expect(growthText(6, undefined)).toBe('–');
  });
});
