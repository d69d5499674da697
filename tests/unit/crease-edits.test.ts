/** The crease editor's parts: edge loops on control meshes, tag edits and their history, applied by the real core. */
import { beforeAll, describe, expect, it } from 'vitest';
import { initNode } from '../../web/core/init-node';
import { parseMesh, subdivide } from '../../web/core/subdiv-core';
import { ControlTopology, type Edge } from '../../web/edit/control-topology';
import { hasTags, noTags, sharpnessOf, TagHistory, withSharpness } from '../../web/edit/tag-edits';
import { loadFixture } from './test-helpers';

beforeAll(async () => {
  await initNode();
});

/** The edges of a loop as "a-b" strings, and a check that each follows the one before. */
function chain(edges: readonly Edge[]): string[] {
  for (let i = 1; i < edges.length; ++i) {
    const shared = edges[i].filter((v) => edges[i - 1].includes(v));
    expect(shared.length, `edges ${i - 1} and ${i} share one vertex`).toBe(1);
  }
  return edges.map(([a, b]) => `${a}-${b}`);
}

describe('control topology', () => {
  it('knows the edges of a mesh and the ring around a vertex', () => {
    // Vertex r * 4 + c of the 3 × 3 grid at (c, r); its faces turn counter-clockwise seen from +z, rings the other way.
    const grid = new ControlTopology(loadFixture('grid-open.off'));
    expect(grid.isEdge(5, 6)).toBe(true);
    expect(grid.isEdge(6, 5)).toBe(true);
    expect(grid.isEdge(5, 10)).toBe(false);
    expect(grid.ringAround(5, 6)).toEqual([6, 1, 4, 9]);
    // A border vertex has no closed ring.
    expect(grid.ringAround(1, 2)).toBeNull();
  });

  it('finds edge loops: straight across valence-4 and valence-6 vertices, stopping at borders', () => {
    const grid = new ControlTopology(loadFixture('grid-open.off'));
    expect(chain(grid.edgeLoop(5, 6))).toEqual(['4-5', '5-6', '6-7']);
    expect(chain(grid.edgeLoop(9, 5))).toEqual(
      ['13-9', '5-9', '1-5'].map((e) =>
        e
          .split('-')
          .sort((a, b) => +a - +b)
          .join('-'),
      ),
    );
    expect(chain(grid.edgeLoop(0, 1))).toEqual(['0-1']);
    // The quad torus: vertex 6i + j; around the tube (6) and around the hole (8), closed.
    const torus = new ControlTopology(loadFixture('torus-quad.off'));
    expect(chain(torus.edgeLoop(0, 1))).toEqual(['0-1', '1-2', '2-3', '3-4', '4-5', '0-5']);
    expect(torus.edgeLoop(0, 6)).toHaveLength(8);
    // The triangulated torus has valence 6 everywhere: the third edge on, the same loops.
    const triangles = new ControlTopology(loadFixture('torus-tri.off'));
    expect(chain(triangles.edgeLoop(0, 1))).toEqual(['0-1', '1-2', '2-3', '3-4', '4-5', '0-5']);
    expect(triangles.edgeLoop(0, 6)).toHaveLength(8);
  });

  it('stops at a vertex of odd valence (a cube corner)', () => {
    const cube = new ControlTopology(loadFixture('cube.off'));
    expect(cube.edgeLoop(0, 1)).toHaveLength(1);
  });
});

describe('tag edits', () => {
  it('sets, changes and removes edge and corner sharpness without touching the input', () => {
    const start = withSharpness(undefined, { kind: 'edges', edges: [[1, 3]] }, 1);
    expect(Array.from(start.creaseEdges)).toEqual([1, 3]);
    expect(Array.from(start.creaseSharpness)).toEqual([1]);
    const loop = withSharpness(
      start,
      {
        kind: 'edges',
        edges: [
          [3, 1],
          [5, 7],
        ],
      },
      2.5,
    );
    expect(Array.from(loop.creaseEdges)).toEqual([1, 3, 5, 7]);
    expect(Array.from(loop.creaseSharpness)).toEqual([2.5, 2.5]);
    expect(Array.from(start.creaseSharpness)).toEqual([1]);
    expect(sharpnessOf(loop, { kind: 'edges', edges: [[7, 5]] })).toEqual({ sharpness: 2.5, mixed: false });
    const mixed = withSharpness(loop, { kind: 'edges', edges: [[0, 1]] }, 12);
    // Above 10 is infinitely sharp: kept as 10.
    expect(
      sharpnessOf(mixed, {
        kind: 'edges',
        edges: [
          [1, 0],
          [1, 3],
        ],
      }),
    ).toEqual({ sharpness: 10, mixed: true });
    const smooth = withSharpness(
      mixed,
      {
        kind: 'edges',
        edges: [
          [1, 3],
          [0, 1],
        ],
      },
      0,
    );
    expect(Array.from(smooth.creaseEdges)).toEqual([5, 7]);
    const corner = withSharpness(smooth, { kind: 'vertex', vertex: 2 }, 3);
    expect(Array.from(corner.cornerVertices)).toEqual([2]);
    expect(sharpnessOf(corner, { kind: 'vertex', vertex: 2 }).sharpness).toBe(3);
    expect(sharpnessOf(corner, { kind: 'vertex', vertex: 4 }).sharpness).toBe(0);
    const none = withSharpness(
      withSharpness(corner, { kind: 'vertex', vertex: 2 }, 0),
      { kind: 'edges', edges: [[5, 7]] },
      -1,
    );
    expect(hasTags(none)).toBe(false);
    expect(hasTags({ ...noTags(), boundaryGiven: true })).toBe(true);
  });

  it('keeps the modes and notes of the file', () => {
    const read = parseMesh(`${loadObjCube()}t interpolateboundary 1/0/0 1\nt creasemethod 0/0/1 chaikin\n`, 'obj');
    const edited = withSharpness(read.tags, { kind: 'edges', edges: [[0, 1]] }, 2);
    expect(edited.boundary).toBe('edge-and-corner');
    expect(edited.creaseMethod).toBe('chaikin');
    expect(edited.boundaryGiven).toBe(true);
  });

  it('is what the reader makes of the same t lines: the core gives the same points', () => {
    const cube = parseMesh(loadObjCube(), 'obj');
    const tags = withSharpness(
      withSharpness(
        undefined,
        {
          kind: 'edges',
          edges: [
            [1, 5],
            [1, 3],
          ],
        },
        2,
      ),
      { kind: 'vertex', vertex: 2 },
      3.5,
    );
    const edited = subdivide({ ...cube, tags }, { scheme: 'catmull-clark', levels: 2 });
    const read = subdivide(parseMesh(`${loadObjCube()}t crease 4/1/0 1 5 1 3 2\nt corner 1/1/0 2 3.5\n`, 'obj'), {
      scheme: 'catmull-clark',
      levels: 2,
    });
    expect(Array.from(edited.positions)).toEqual(Array.from(read.positions));
    const untagged = subdivide(cube, { scheme: 'catmull-clark', levels: 2 });
    expect(Array.from(edited.positions)).not.toEqual(Array.from(untagged.positions));
  });
});

describe('tag history', () => {
  it('undoes and redoes edits in order, each recorded once applied; a new edit forgets what was undone', () => {
    const a = withSharpness(undefined, { kind: 'vertex', vertex: 0 }, 1);
    const b = withSharpness(a, { kind: 'vertex', vertex: 1 }, 2);
    const history = new TagHistory();
    expect(history.undoTarget()).toBeNull();
    history.push(undefined); // undefined -> a
    history.push(a); // a -> b
    expect(history.undoTarget()).toEqual({ tags: a });
    // Not applied (a failed step): nothing changes.
    expect(history.undoTarget()).toEqual({ tags: a });
    history.undone(b);
    expect(history.undoTarget()).toEqual({ tags: undefined });
    history.undone(a);
    expect(history.canUndo).toBe(false);
    expect(history.redoTarget()).toEqual({ tags: a });
    history.redone(undefined);
    expect(history.redoTarget()).toEqual({ tags: b });
    history.push(a); // a -> c
    expect(history.canRedo).toBe(false);
    expect(history.undoTarget()).toEqual({ tags: a });
    history.clear();
    expect(history.canUndo).toBe(false);
  });
});

/** The cube of cube-creased.obj without its tags: faces 2 1 3 4, ... (vertex 0 at the origin). */
function loadObjCube(): string {
  return (
    'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n' +
    'f 2 1 3 4\nf 3 1 5 7\nf 4 3 7 8\nf 5 1 2 6\nf 6 2 4 8\nf 7 5 6 8\n'
  );
}
