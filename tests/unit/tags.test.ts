/** OpenSubdiv's tags through the real WASM core: parsed into typed arrays, written back exactly, refused with their line. */
import { beforeAll, describe, expect, it } from 'vitest';
import { initNode } from '../../web/core/init-node';
import type { Mesh, MeshTags } from '../../web/core/mesh';
import { exportMesh, parseMesh, predictSize, subdivide } from '../../web/core/subdiv-core';
import { SubdivError } from '../../web/core/subdiv-error';
import { fixtureText, loadFixture } from './test-helpers';

beforeAll(async () => {
  await initNode();
});

/** The cube [0,1]^3 as in cube-creased.obj: lines 1-14; a tag appended is on line 15. */
const CUBE_OBJ =
  'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n' +
  'f 2 1 3 4\nf 3 1 5 7\nf 4 3 7 8\nf 5 1 2 6\nf 6 2 4 8\nf 7 5 6 8\n';

function errorOf(run: () => unknown): SubdivError {
  try {
    run();
  } catch (error) {
    expect(error).toBeInstanceOf(SubdivError);
    return error as SubdivError;
  }
  throw new Error('expected a SubdivError');
}

function plainTags(tags: MeshTags | undefined) {
  if (!tags) return undefined;
  return {
    ...tags,
    creaseEdges: Array.from(tags.creaseEdges),
    creaseSharpness: Array.from(tags.creaseSharpness),
    cornerVertices: Array.from(tags.cornerVertices),
    cornerSharpness: Array.from(tags.cornerSharpness),
    holes: Array.from(tags.holes),
  };
}

describe('tags read from OBJ', () => {
  it('cube-creased.obj: typed arrays with the values of its tag lines', () => {
    const { tags } = loadFixture('cube-creased.obj');
    expect(tags).toBeDefined();
    const t = tags as MeshTags;
    expect(t.creaseEdges).toBeInstanceOf(Uint32Array);
    expect(t.creaseSharpness).toBeInstanceOf(Float32Array);
    expect(t.cornerVertices).toBeInstanceOf(Uint32Array);
    expect(t.cornerSharpness).toBeInstanceOf(Float32Array);
    expect(t.holes).toBeInstanceOf(Uint32Array);
    expect(plainTags(t)).toEqual({
      creaseEdges: [4, 5, 5, 7, 0, 1, 1, 3],
      creaseSharpness: [2, 2, 3.5, 3.5],
      cornerVertices: [6],
      cornerSharpness: [4.25],
      holes: [],
      boundary: 'edge',
      boundaryGiven: true,
      creaseMethod: 'uniform',
      creaseMethodGiven: false,
      notes: [],
    });
  });

  it('the other fixtures: corners and border mode, holes, chaikin creasing', () => {
    const patch = loadFixture('quad-patch-corners.obj').tags as MeshTags;
    expect(Array.from(patch.cornerVertices)).toEqual([0, 3, 12, 15]);
    expect(Array.from(patch.cornerSharpness)).toEqual([10, 10, 10, 10]);
    expect(patch.boundary).toBe('edge-and-corner');
    expect(Array.from((loadFixture('torus-holed.obj').tags as MeshTags).holes)).toEqual([3, 14]);
    const tetra = loadFixture('tetra-crease.obj').tags as MeshTags;
    expect(Array.from(tetra.creaseEdges)).toEqual([0, 1]);
    expect(Array.from(tetra.creaseSharpness)).toEqual([1.5]);
    expect(tetra.creaseMethod).toBe('chaikin');
    expect(tetra.creaseMethodGiven).toBe(true);
  });

  it('a mesh without tags has no tags object', () => {
    expect(loadFixture('cube.obj').tags).toBeUndefined();
    expect(loadFixture('cube.off').tags).toBeUndefined();
    expect('tags' in parseMesh(CUBE_OBJ, 'obj')).toBe(false);
  });

  it('an unapplied tag loads with a note naming its line', () => {
    const { tags } = parseMesh(`${CUBE_OBJ}t smoothtriangles 1/0/0 1\n`, 'obj');
    expect(tags?.notes).toEqual(["line 15: tag 'smoothtriangles' is not applied"]);
    expect(tags?.creaseEdges.length).toBe(0);
  });

  it('OFF reads "# t ..." comments after the faces as tags', () => {
    const off = exportMesh(parseMesh(CUBE_OBJ, 'obj'), 'off');
    const { tags } = parseMesh(`${off}# a comment\n# t crease 2/1/0 0 1 2.5\n# t hole 1/0/0 2\n`, 'off');
    expect(Array.from(tags?.creaseEdges ?? [])).toEqual([0, 1]);
    expect(Array.from(tags?.creaseSharpness ?? [])).toEqual([2.5]);
    expect(Array.from(tags?.holes ?? [])).toEqual([2]);
  });
});

describe('tags written back', () => {
  it.each(['cube-creased.obj', 'quad-patch-corners.obj', 'torus-holed.obj', 'tetra-crease.obj'])(
    '%s: OBJ and OFF round trips give the same tags and the same text',
    (name) => {
      const mesh = loadFixture(name);
      for (const format of ['obj', 'off'] as const) {
        const text = exportMesh(mesh, format);
        const back = parseMesh(text, format);
        expect(plainTags(back.tags)).toEqual(plainTags(mesh.tags));
        expect(exportMesh(back, format)).toBe(text);
      }
    },
  );

  it('tags given in JS as float32 values come back bitwise (2.3, 0.5, 10, 11.5)', () => {
    const cube = parseMesh(CUBE_OBJ, 'obj');
    const mesh: Mesh = {
      ...cube,
      tags: {
        creaseEdges: new Uint32Array([4, 5, 5, 7, 0, 1, 1, 3]),
        creaseSharpness: new Float32Array([2.3, 0.5, 10, 11.5]),
        cornerVertices: new Uint32Array([6]),
        cornerSharpness: new Float32Array([1 / 3]),
        holes: new Uint32Array([5, 2]),
        boundary: 'none',
        boundaryGiven: false,
        creaseMethod: 'chaikin',
        creaseMethodGiven: false,
        notes: ['not written'],
      },
    };
    const obj = exportMesh(mesh, 'obj');
    expect(obj.slice(obj.indexOf('\nt ') + 1)).toBe(
      't crease 2/1/0 4 5 2.3\nt crease 2/1/0 5 7 0.5\nt crease 2/1/0 0 1 10\nt crease 2/1/0 1 3 11.5\n' +
        't corner 1/1/0 6 0.33333334\nt hole 2/0/0 5 2\nt interpolateboundary 1/0/0 0\nt creasemethod 0/0/1 chaikin\n',
    );
    const back = parseMesh(obj, 'obj').tags as MeshTags;
    expect(back.creaseSharpness).toEqual(mesh.tags?.creaseSharpness);
    expect(back.cornerSharpness).toEqual(mesh.tags?.cornerSharpness);
    expect(Array.from(back.holes)).toEqual([2, 5]);
  });

  it('a mesh without tags is written exactly as before', () => {
    expect(exportMesh(parseMesh(CUBE_OBJ, 'obj'), 'obj')).toBe(CUBE_OBJ);
    expect(exportMesh(loadFixture('cube.off'), 'off')).not.toContain('#');
  });

  it('tags that would not read back are refused as invalid_mesh', () => {
    const cube = parseMesh(fixtureText('cube-creased.obj'), 'obj');
    const tags = cube.tags as MeshTags;
    const notAnEdge = { ...cube, tags: { ...tags, creaseEdges: new Uint32Array([0, 7, 5, 7, 0, 1, 1, 3]) } };
    const e = errorOf(() => exportMesh(notAnEdge, 'obj'));
    expect(e.code).toBe('invalid_mesh');
    expect(e.message).toBe('tags: crease 0 7 is not an edge of the mesh');
    const badBoundary = { ...cube, tags: { ...tags, boundary: 'sharp' } } as unknown as Mesh;
    const b = errorOf(() => exportMesh(badBoundary, 'obj'));
    expect(b.code).toBe('invalid_argument');
    expect(b.message).toBe('Mesh tags\' boundary must be "edge", "edge-and-corner" or "none", not "sharp".');
  });
});

describe('bad tags', () => {
  it.each([
    ['t crease 2/1/0 0 1', "line 15: tag 'crease' needs 3 values after its counts '2/1/0', found 2"],
    ['t crease 2/1/0 0 7 2', "line 15: tag 'crease': vertices 0 and 7 are not joined by an edge of the mesh"],
    ['t hole 1/0/0 6', "line 15: tag 'hole': face 6 is out of range (6 faces; tag indices start at 0)"],
    [
      't corner 1/1/0 2 -1',
      "line 15: tag 'corner': sharpness '-1' is negative (0 is smooth, 10 and more infinitely sharp)",
    ],
    ['t creasemethod 0/0/1 smooth', "line 15: tag 'creasemethod': 'smooth' is not normal or chaikin"],
  ])('%s: parse_error on line 15', (tag, message) => {
    const e = errorOf(() => parseMesh(`${CUBE_OBJ}${tag}\nv 2 2 2\n`, 'obj'));
    expect(e.code).toBe('parse_error');
    expect(e.line).toBe(15);
    expect(e.message).toBe(message);
  });

  it('random tag lines are read or refused as parse_error on their own line, never anything else', () => {
    let seed = 16;
    const random = () => {
      seed = (seed * 1103515245 + 12345) % 2147483648;
      return seed / 2147483648;
    };
    const pick = <T>(from: T[]): T => from[Math.floor(random() * from.length)];
    const names = ['crease', 'corner', 'hole', 'interpolateboundary', 'creasemethod', 'smoothtriangles', 'x'];
    const counts = ['2/1/0', '4/1/0', '1/1/0', '1/0/0', '0/0/1', '3/1/0', '2/0/0', '1/1', 'a/b/c'];
    const values = ['0', '1', '2', '3', '5', '7', '8', '-1', '0.5', '10', 'nan', '1e39', 'x', 'chaikin', 'normal'];
    const ints = ['0', '1', '2', '3', '4', '5', '7', '9', '-1', 'x'];
    const floats = ['0', '0.5', '2', '10', '-1', 'inf'];
    const strings = ['chaikin', 'normal', 'smooth'];
    let accepted = 0;
    let refused = 0;
    for (let i = 0; i < 400; i++) {
      const words = ['t', pick(names)];
      if (i % 2 === 0) {
        // Counts that match the values: mostly well formed.
        const n = [0, 1, 2].map(() => Math.floor(random() * 3));
        words.push(n.join('/'));
        for (let k = 0; k < n[0]; k++) words.push(pick(ints));
        for (let k = 0; k < n[1]; k++) words.push(pick(floats));
        for (let k = 0; k < n[2]; k++) words.push(pick(strings));
      } else {
        words.push(pick(counts));
        const n = Math.floor(random() * 5);
        for (let k = 0; k < n; k++) words.push(pick(values));
      }
      const line = words.join(' ');
      try {
        parseMesh(`${CUBE_OBJ}${line}\n# end\n`, 'obj');
        accepted++;
      } catch (error) {
        expect(error, line).toBeInstanceOf(SubdivError);
        const e = error as SubdivError;
        expect(e.code, `${line}: ${e.message}`).toBe('parse_error');
        expect(e.line, `${line}: ${e.message}`).toBe(15);
        expect(e.message.startsWith('line 15: '), e.message).toBe(true);
        refused++;
      }
    }
    expect(accepted).toBeGreaterThan(10);
    expect(refused).toBeGreaterThan(100);
  });
});

describe('subdivide options for tags', () => {
  it('creaseMethod and boundary: the known names are taken, others refused as invalid_argument', () => {
    const mesh = loadFixture('cube-creased.obj');
    const options = { scheme: 'catmull-clark' as const, levels: 1 };
    expect(subdivide(mesh, { ...options, creaseMethod: 'chaikin', boundary: 'edge-and-corner' }).faceSizes.length).toBe(
      24,
    );
    expect(predictSize(mesh, { ...options, creaseMethod: 'uniform', boundary: 'none' }).faces).toBe(24);
    const method = errorOf(() => subdivide(mesh, { ...options, creaseMethod: 'smooth' as 'uniform' }));
    expect(method.code).toBe('invalid_argument');
    expect(method.message).toBe('Option creaseMethod must be "uniform" or "chaikin", not "smooth".');
    const boundary = errorOf(() => predictSize(mesh, { ...options, boundary: 2 as unknown as 'edge' }));
    expect(boundary.code).toBe('invalid_argument');
    expect(boundary.message).toBe('Option boundary must be "edge", "edge-and-corner" or "none", not a number.');
  });
});
