/** Requests a hostile user makes through the API and the CLI: huge level counts, overflowing coordinates. */
import { spawnSync } from 'node:child_process';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { beforeAll, describe, expect, it } from 'vitest';
import { initNode } from '../../web/core/init-node';
import type { SubdivideOptions } from '../../web/core/mesh';
import { exportMesh, meshFacts, parseMesh, predictSize, subdivide } from '../../web/core/subdiv-core';
import { SubdivError } from '../../web/core/subdiv-error';
import { FIXTURES_DIR, loadFixture } from './test-helpers';

const BIN = join(dirname(fileURLToPath(import.meta.url)), '..', '..', 'bin', 'subdiv.mjs');

beforeAll(async () => {
  await initNode();
});

function failure(run: () => unknown): SubdivError {
  try {
    run();
  } catch (error) {
    expect(error).toBeInstanceOf(SubdivError);
    return error as SubdivError;
  }
  return expect.fail('expected a SubdivError');
}

/** What the core says about level 12 of the cube, the first that does not fit (level 11, 25.2 M faces, does since the fast hosts). */
const CUBE_LEVEL_12 =
  /^level 12 of catmull-clark would need about [\d.]+ GB \(predicted 101 M vertices, 101 M faces\), more than the [\d.]+ GB available$/;

describe('level counts beyond 32 bits', () => {
  it.each([2 ** 31, 2 ** 32 + 1, 1e20])('levels %d is refused by the memory check, like levels 1e9', (levels) => {
    const cube = loadFixture('cube.off');
    const error = failure(() => subdivide(cube, { scheme: 'catmull-clark', levels }));
    expect(error.code).toBe('too_large');
    expect(error.message).toMatch(CUBE_LEVEL_12);
    // The module still works.
    expect(meshFacts(subdivide(cube, { scheme: 'catmull-clark', levels: 1 })).faces).toBe(24);
  });

  it.each([
    [{ levels: 1.5 }, 'Option levels must be a whole number, 0 or more.'],
    [{ levels: Number.POSITIVE_INFINITY }, 'Option levels must be a whole number, 0 or more.'],
    [{ levels: Number.NaN }, 'Option levels must be a whole number, 0 or more.'],
    [{ levels: 1, startLevel: 2 ** 31 }, 'Option startLevel must be a whole number from 0 to 1000000000.'],
  ] as [Partial<SubdivideOptions>, string][])('%o is an invalid_argument', (options, message) => {
    const error = failure(() => subdivide(loadFixture('cube.off'), { scheme: 'catmull-clark', levels: 1, ...options }));
    expect(error.code).toBe('invalid_argument');
    expect(error.message).toBe(message);
  });

  it('the CLI reports --levels 2147483648 as the memory check does, naming the file', () => {
    const r = spawnSync(process.execPath, [BIN, 'cube.off', '--levels', '2147483648', '--stats'], {
      cwd: FIXTURES_DIR,
      encoding: 'utf8',
    });
    expect(r.status).toBe(1);
    expect(r.stdout).toBe('');
    const [line, rest] = r.stderr.split('\n');
    expect(rest).toBe('');
    expect(line.startsWith('error: cube.off: level 12 of catmull-clark would need about ')).toBe(true);
    expect(line.slice('error: cube.off: '.length)).toMatch(CUBE_LEVEL_12);
  });
});

describe('predictions beyond 32 bits', () => {
  it('predictSize gives level 16 of the cube exactly, not saturated at 4294967295', () => {
    // Catmull-Clark on the cube: F = 6 * 4^16 quads, E = 2F, V = E - F + 2.
    const p = predictSize(loadFixture('cube.off'), { scheme: 'catmull-clark', levels: 16 });
    expect([p.vertices, p.edges, p.faces]).toEqual([25769803778, 51539607552, 25769803776]);
    // Tens of bytes per face (73 since the primal points need no scratch): far beyond 4 GB.
    expect(p.peakBytes).toBeGreaterThan(50 * 25769803776);
  });
});

describe('coordinates near the largest double', () => {
  const quad = (c: string) => `OFF\n4 1 0\n0 0 0\n${c} 0 0\n${c} ${c} 0\n0 ${c} 0\n4 0 1 2 3\n`;

  it('a step that overflows fails with invalid_mesh instead of returning infinite coordinates', () => {
    const mesh = parseMesh(quad('1.7e308'), 'off');
    const error = failure(() => subdivide(mesh, { scheme: 'catmull-clark', levels: 1 }));
    expect(error.code).toBe('invalid_mesh');
    expect(error.message).toBe(
      "level 1 of catmull-clark overflows: a new coordinate is not finite (the input's coordinates reach 1.7e+308; " +
        'coordinates or weights this large exceed double precision arithmetic, scale the mesh down)',
    );
    // 1e300 leaves room: the centre of the square is the face point.
    const ok = subdivide(parseMesh(quad('1e300'), 'off'), { scheme: 'catmull-clark', levels: 1 });
    expect(Array.from(ok.positions).every(Number.isFinite)).toBe(true);
    expect(meshFacts(ok).faces).toBe(4);
  });
});

describe('exportMesh on buffers that do not describe a mesh', () => {
  const positions = new Float64Array([0, 0, 0, 1, 0, 0, 0, 1, 0]);
  const controlEdges = new Uint32Array();

  it('refuses face sizes that run past the indices instead of writing heap bytes as indices', () => {
    const mesh = { positions, faceSizes: new Uint32Array([40]), faceIndices: new Uint32Array([0, 1, 2]), controlEdges };
    const error = failure(() => exportMesh(mesh, 'off'));
    expect(error.code).toBe('invalid_mesh');
    expect(error.message).toBe('face sizes add up to 40 indices but there are 3');
  });

  it('refuses a non-finite coordinate, which it would write as "nan"', () => {
    const mesh = {
      positions: new Float64Array([0, 0, 0, 1, 0, 0, Number.NaN, 1, 0]),
      faceSizes: new Uint32Array([3]),
      faceIndices: new Uint32Array([0, 1, 2]),
      controlEdges,
    };
    const error = failure(() => exportMesh(mesh, 'off'));
    expect(error.code).toBe('invalid_mesh');
    expect(error.message).toBe('vertex 2 has a non-finite coordinate');
  });

  it('refuses an index past the vertices, which no reader could take back', () => {
    const mesh = { positions, faceSizes: new Uint32Array([3]), faceIndices: new Uint32Array([0, 1, 7]), controlEdges };
    const error = failure(() => exportMesh(mesh, 'obj'));
    expect(error.code).toBe('invalid_mesh');
    expect(error.message).toBe('vertex index 7 is out of range (3 vertices)');
    // The module still works.
    expect(exportMesh({ ...mesh, faceIndices: new Uint32Array([0, 1, 2]) }, 'obj')).toBe(
      'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n',
    );
  });
});
