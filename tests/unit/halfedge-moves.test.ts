/**
 * The halfedge explorer's walks (web/teach/halfedge-moves.ts) on tables the
 * real core makes: CGAL's spelling of a path, the moves' identities (next
 * four times round a quad, opposite twice, prev undoing next), and the
 * circulations' degrees against the mesh's own faces and valences.
 */
import { beforeAll, describe, expect, it } from 'vitest';
import { initNode } from '../../web/core/init-node';
import { halfedgeTable } from '../../web/core/subdiv-core';
import { sizeRefusal } from '../../web/teach/halfedge-explorer';
import {
  cgalExpressions,
  circulate,
  circulationReport,
  extendWalk,
  MAX_PATH,
  moveHalfedge,
  sourceOf,
} from '../../web/teach/halfedge-moves';
import { loadFixture, toPlain } from './test-helpers';

beforeAll(async () => {
  await initNode();
});

describe('cgalExpressions', () => {
  it('spells a path for Surface_mesh and Polyhedron_3', () => {
    expect(cgalExpressions([])).toEqual({ surfaceMesh: 'h', polyhedron: 'h' });
    expect(cgalExpressions(['opposite', 'next'])).toEqual({
      surfaceMesh: 'next(opposite(h, m), m)',
      polyhedron: 'h->opposite()->next()',
    });
    expect(cgalExpressions(['prev', 'around-vertex', 'around-face'])).toEqual({
      surfaceMesh: 'next(opposite(next(prev(h, m), m), m), m)',
      polyhedron: 'h->prev()->next()->opposite()->next()',
    });
  });
});

describe('walks on the cube', () => {
  const cube = () => halfedgeTable(loadFixture('cube.off'));

  it('next four times and opposite twice come back; prev undoes next', () => {
    const table = cube();
    expect(table.next.length).toBe(24);
    for (let h = 0; h < 24; ++h) {
      let g = h;
      for (let i = 0; i < 4; ++i) g = moveHalfedge(table, g, 'next');
      expect(g).toBe(h);
      expect(moveHalfedge(table, moveHalfedge(table, h, 'opposite'), 'opposite')).toBe(h);
      expect(moveHalfedge(table, moveHalfedge(table, h, 'next'), 'prev')).toBe(h);
      expect(moveHalfedge(table, h, 'around-vertex')).not.toBe(h);
      expect(table.target[moveHalfedge(table, h, 'around-vertex')]).toBe(table.target[h]);
      expect(sourceOf(table, h)).toBe(table.target[table.prev[h]]);
    }
  });

  it('circulates a corner (3 halfedges) and a face (4), each with its report', () => {
    const table = cube();
    const around = circulate(table, 0, 'vertex');
    expect(around).toHaveLength(3);
    expect(new Set(around.map((g) => table.target[g]))).toEqual(new Set([table.target[0]]));
    expect(circulationReport(table, 0, 'vertex', 3)).toBe(`vertex ${table.target[0]}: 3 halfedges around it`);
    const face = circulate(table, 0, 'face');
    expect(face).toHaveLength(4);
    expect(new Set(face.map((g) => table.face[g]))).toEqual(new Set([table.face[0]]));
  });

  it('folds moves past MAX_PATH into the start, still reaching the same halfedge', () => {
    const table = cube();
    let walk: { from: number; path: ReturnType<typeof extendWalk>['path'] } = { from: 5, path: [] };
    let h = 5;
    const moves = ['next', 'opposite', 'around-vertex', 'prev', 'next', 'opposite', 'next', 'around-face'] as const;
    for (const move of moves) {
      walk = extendWalk(table, walk, move);
      h = moveHalfedge(table, h, move);
    }
    expect(walk.path).toHaveLength(MAX_PATH);
    expect(walk.path).toEqual(moves.slice(moves.length - MAX_PATH));
    expect(walk.path.reduce((g, m) => moveHalfedge(table, g, m), walk.from)).toBe(h);
  });
});

describe('circulations against the mesh', () => {
  it('every vertex degree of the open grid is its valence; border loops have the boundary length', () => {
    const mesh = loadFixture('grid-open.off');
    const table = halfedgeTable(mesh);
    const { faces } = toPlain(mesh);
    const valence = new Map<number, Set<number>>();
    for (const f of faces)
      f.forEach((v, i) => {
        const w = f[(i + 1) % f.length];
        for (const [a, b] of [
          [v, w],
          [w, v],
        ]) {
          const set = valence.get(a) ?? new Set<number>();
          set.add(b);
          valence.set(a, set);
        }
      });
    for (let h = 0; h < table.next.length; ++h) {
      expect(circulate(table, h, 'vertex')).toHaveLength(valence.get(table.target[h])?.size ?? -1);
      const f = table.face[h];
      if (f >= 0) expect(circulate(table, h, 'face')).toHaveLength(faces[f].length);
    }
    const border = [...table.face.keys()].find((h) => table.face[h] < 0) ?? -1;
    const loop = circulate(table, border, 'face');
    expect(loop.every((g) => table.face[g] === -1)).toBe(true);
    expect(circulationReport(table, border, 'face', loop.length)).toBe(
      `border loop: ${loop.length} halfedges around it`,
    );
  });
});

describe('sizeRefusal', () => {
  it('names the levels small enough, or asks for a smaller mesh', () => {
    expect(sizeRefusal(24576, [24, 96, 384, 1536, 6144, 24576])).toBe(
      'The halfedge explorer shows meshes up to 5,000 halfedges; this level has 24,576. Pick level 0, 1, 2 or 3.',
    );
    expect(sizeRefusal(6144, [120, 6144])).toMatch(/has 6,144\. Pick level 0\.$/);
    expect(sizeRefusal(9000, [9000])).toMatch(/Load a smaller mesh\.$/);
  });
});
