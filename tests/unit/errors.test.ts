/** Errors cross as one typed SubdivError, and the instance keeps working after any of them. */
import { beforeAll, describe, expect, it } from 'vitest';
import { initNode } from '../../web/core/init-node';
import type { Mesh, MeshFormat } from '../../web/core/mesh';
import {
  heapBytesInUse,
  meshFacts,
  parseMesh,
  predictSize,
  subdivide,
  throwForTesting,
} from '../../web/core/subdiv-core';
import { SubdivError, type SubdivErrorCode } from '../../web/core/subdiv-error';
import { expectCounts, loadFixture } from './test-helpers';

beforeAll(async () => {
  await initNode();
});

function caught(action: () => unknown): SubdivError {
  try {
    action();
  } catch (error) {
    expect(error).toBeInstanceOf(SubdivError);
    return error as SubdivError;
  }
  return expect.fail('expected a SubdivError');
}

/** The module still parses and subdivides correctly. */
function expectWorking(): void {
  const cube = loadFixture('cube.off');
  expectCounts(meshFacts(subdivide(cube, { scheme: 'catmull-clark', levels: 2 })), {
    vertices: 98,
    edges: 192,
    faces: 96,
  });
}

const CUBE_HEAD = 'OFF\n8 6 0\n-1 -1 -1\n1 -1 -1\n1 1 -1\n-1 1 -1\n-1 -1 1\n1 -1 1\n1 1 1\n-1 1 1\n';
const CUBE_FACES = ['4 0 3 2 1', '4 4 5 6 7', '4 0 1 5 4', '4 1 2 6 5', '4 2 3 7 6', '4 3 0 4 7'];
/** The cube with face `f` (0-based; on line 11 + f) replaced. */
function cubeWithFace(f: number, face: string): string {
  const faces = [...CUBE_FACES];
  faces[f] = face;
  return `${CUBE_HEAD}${faces.join('\n')}\n`;
}

interface Case {
  name: string;
  text: string;
  format: MeshFormat;
  code: SubdivErrorCode;
  line: number;
  message: RegExp;
}

const cases: Case[] = [
  {
    name: 'index out of range',
    text: cubeWithFace(4, '4 2 3 12 6'),
    format: 'off',
    code: 'invalid_mesh',
    line: 15,
    message: /face index 12 is out of range \(8 vertices\)/,
  },
  {
    name: 'face with fewer than 3 vertices',
    text: cubeWithFace(0, '2 0 3'),
    format: 'off',
    code: 'invalid_mesh',
    line: 11,
    message: /has 2 vertices; a face needs at least 3/,
  },
  {
    name: 'repeated vertex in a face',
    text: cubeWithFace(1, '4 4 5 5 7'),
    format: 'off',
    code: 'invalid_mesh',
    line: 12,
    message: /uses vertex 5 more than once/,
  },
  {
    name: 'non-numeric coordinate',
    text: CUBE_HEAD.replace('1 1 -1', '1 abc -1') + CUBE_FACES.join('\n'),
    format: 'off',
    code: 'parse_error',
    line: 5,
    message: /not a number: 'abc'/,
  },
  {
    name: 'non-finite coordinate',
    text: CUBE_HEAD.replace('1 1 1', '1 inf 1') + CUBE_FACES.join('\n'),
    format: 'off',
    code: 'parse_error',
    line: 9,
    message: /not finite/,
  },
  {
    name: 'truncated file',
    text: `${CUBE_HEAD}${CUBE_FACES.slice(0, 4).join('\n')}\n`,
    format: 'off',
    code: 'parse_error',
    line: 14,
    message: /file ends after 4 of 6 faces/,
  },
  {
    name: 'header counts that disagree with the data',
    text: `${CUBE_HEAD}${CUBE_FACES.join('\n')}\n3 0 1 2\n`,
    format: 'off',
    code: 'parse_error',
    line: 17,
    message: /header counts disagree/,
  },
  {
    name: 'a huge declared count fails where the data ends, without allocating for it',
    text: 'OFF 2000000000 2000000000 0\n0 0 0\n',
    format: 'off',
    code: 'parse_error',
    line: 2,
    message: /file ends after 1 of 2000000000 vertices/,
  },
  {
    name: 'non-manifold edge',
    text: 'OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n',
    format: 'off',
    code: 'invalid_mesh',
    line: 0,
    message: /non-manifold edge between vertices 0 and 1: used by 3 faces/,
  },
  {
    name: 'non-manifold vertex',
    text: 'OFF\n5 2 0\n0 0 0\n1 0 0\n0 1 0\n-1 0 0\n0 -1 0\n3 0 1 2\n3 0 3 4\n',
    format: 'off',
    code: 'invalid_mesh',
    line: 0,
    message: /non-manifold vertex 0/,
  },
  {
    name: 'inconsistent orientation',
    // Both faces use the edge 2→0.
    text: 'OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 2 0 3\n',
    format: 'off',
    code: 'inconsistent_orientation',
    line: 0,
    message: /inconsistent orientation: .*; turning 1 face around makes them agree/,
  },
  {
    name: 'no faces',
    text: 'OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n',
    format: 'off',
    code: 'invalid_mesh',
    line: 0,
    message: /no faces/,
  },
  {
    name: 'OBJ face index 0',
    text: 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n',
    format: 'obj',
    code: 'invalid_mesh',
    line: 4,
    message: /face index 0 is out of range \(OBJ indices start at 1\)/,
  },
  {
    name: 'OBJ relative index before its vertex',
    text: 'v 0 0 0\nv 1 0 0\nf -1 -2 -3\nv 0 1 0\n',
    format: 'obj',
    code: 'invalid_mesh',
    line: 3,
    message: /relative face index -3 is out of range \(2 vertices defined so far\)/,
  },
];

describe('invalid input', () => {
  it.each(cases)('$name → $code, line $line', ({ text, format, code, line, message }) => {
    const error = caught(() => parseMesh(text, format));
    expect(error.code).toBe(code);
    expect(error.message).toMatch(message);
    if (line > 0) expect(error.line).toBe(line);
    expectWorking();
  });

  it('an unknown format is an invalid_argument', () => {
    const error = caught(() => parseMesh('OFF\n', 'fbx' as MeshFormat));
    expect(error.code).toBe('invalid_argument');
    expect(error.message).toMatch(/fbx/);
  });

  it('buffers from JS are checked as files are', () => {
    const bad: Mesh = {
      positions: new Float64Array([0, 0, 0, 1, 0, 0, 0, 1, 0]),
      faceSizes: new Uint32Array([3]),
      faceIndices: new Uint32Array([0, 1, 7]),
      controlEdges: new Uint32Array(0),
    };
    const error = caught(() => subdivide(bad, { scheme: 'loop', levels: 1 }));
    expect(error.code).toBe('invalid_mesh');
    expect(error.message).toMatch(/vertex index 7 is out of range \(3 vertices\)/);
    const nan: Mesh = {
      ...bad,
      positions: new Float64Array([0, 0, 0, 1, Number.NaN, 0, 0, 1, 0]),
      faceIndices: new Uint32Array([0, 1, 2]),
    };
    expect(caught(() => meshFacts(nan)).message).toMatch(/non-finite/);
    const sizes: Mesh = { ...bad, faceSizes: new Uint32Array([4]) };
    expect(caught(() => meshFacts(sizes)).message).toMatch(/face sizes add up to 4 indices but there are 3/);
    expectWorking();
  });
});

describe('the module keeps working', () => {
  it('after a step refused as too_large for a small memory limit', () => {
    const torus = loadFixture('torus-quad.off');
    const p = predictSize(torus, { scheme: 'catmull-clark', levels: 3 });
    const error = caught(() =>
      subdivide(torus, { scheme: 'catmull-clark', levels: 3, memoryLimitBytes: Math.floor(p.peakBytes / 2) }),
    );
    expect(error.code).toBe('too_large');
    expect(error.message).toMatch(/\d/);
    expectWorking();
  });

  it('after a step too large for the 4 GB heap, refused before anything is allocated', () => {
    const before = heapBytesInUse();
    const torus = loadFixture('torus-quad.off');
    const error = caught(() => subdivide(torus, { scheme: 'catmull-clark', levels: 12 }));
    expect(error.code).toBe('too_large');
    expect(heapBytesInUse()).toBeLessThan(before + (64 << 20));
    expectWorking();
  });

  it.each([
    [
      'cgal',
      'internal_error',
      /^Internal error: CGAL check failed: is_triangle_mesh\(mesh\) \(raised by throw_for_test\)$/,
    ],
    ['std', 'internal_error', /raised by throw_for_test/],
    ['alloc', 'too_large', /memory/i],
    ['other', 'internal_error', /unknown exception/],
  ] as const)('after a %s exception inside the core', (kind, code, message) => {
    const error = caught(() => throwForTesting(kind));
    expect(error.code).toBe(code);
    expect(error.message).toMatch(message);
    expectWorking();
  });

  it('leaks nothing across many calls', () => {
    const cube = loadFixture('cube.off');
    const run = () => {
      for (let i = 0; i < 20; i++) {
        meshFacts(subdivide(cube, { scheme: 'doo-sabin', levels: 2 }));
        try {
          parseMesh('OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n', 'off');
        } catch {
          // expected
        }
      }
    };
    run();
    const before = heapBytesInUse();
    run();
    expect(heapBytesInUse()).toBe(before);
  });
});
