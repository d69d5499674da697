/** Writing in pieces (writeMesh, exportMeshChunks) and reading from bytes, through the real WASM core. */
import { readdirSync } from 'node:fs';
import { join } from 'node:path';
import { beforeAll, describe, expect, it } from 'vitest';
import { initNode } from '../../web/core/init-node';
import type { Mesh } from '../../web/core/mesh';
import {
  DEFAULT_CHUNK_BYTES,
  exportMesh,
  exportMeshChunks,
  formatFromFileName,
  meshFacts,
  parseForView,
  parseMesh,
  subdivide,
  writeMesh,
} from '../../web/core/subdiv-core';
import { SubdivError } from '../../web/core/subdiv-error';
import { expectSamePoints, FIXTURES_DIR, fixtureText, loadFixture } from './test-helpers';

beforeAll(async () => {
  await initNode();
});

function joined(chunks: Uint8Array[]): string {
  const decoder = new TextDecoder();
  return chunks.map((chunk) => decoder.decode(chunk)).join('');
}

/** A triangle and one more vertex per three coordinates given. */
function meshWith(coordinates: number[]): Mesh {
  return {
    positions: new Float64Array([0, 0, 0, 1, 0, 0, 0, 1, 0, ...coordinates]),
    faceSizes: new Uint32Array([3]),
    faceIndices: new Uint32Array([0, 1, 2]),
    controlEdges: new Uint32Array(),
  };
}

describe('exported text', () => {
  it('writes coordinates exactly as printf("%.17g") does, ties to even included', () => {
    // Expected strings from C's printf; 1 + 2^-17 = 1.00000762939453125 is a tie at the 17th digit.
    const text = exportMesh(
      meshWith([
        0.1,
        1 / 3,
        1 + 2 ** -17,
        -0,
        1e-5,
        5e-324,
        1e17,
        123456789012345680,
        1e16,
        -1234.5678,
        2.5,
        1.7976931348623157e308,
      ]),
      'obj',
    );
    expect(text).toBe(
      'v 0 0 0\nv 1 0 0\nv 0 1 0\n' +
        'v 0.10000000000000001 0.33333333333333331 1.0000076293945312\n' +
        'v -0 1.0000000000000001e-05 4.9406564584124654e-324\n' +
        'v 1e+17 1.2345678901234568e+17 10000000000000000\n' +
        'v -1234.5678 2.5 1.7976931348623157e+308\n' +
        'f 1 2 3\n',
    );
  });
});

describe('writing in pieces', () => {
  let big: Mesh;
  beforeAll(() => {
    big = subdivide(loadFixture('torus-quad.off'), { scheme: 'catmull-clark', levels: 4 });
  });

  it.each(['off', 'obj'] as const)('%s: the pieces join to exportMesh text and none exceeds its bound', (format) => {
    const whole = exportMesh(big, format);
    expect(whole.length).toBeGreaterThan(1_000_000);
    for (const bound of [64, 1000, 65536, DEFAULT_CHUNK_BYTES]) {
      const chunks = exportMeshChunks(big, format, bound);
      expect(joined(chunks)).toBe(whole);
      expect(Math.max(...chunks.map((c) => c.length))).toBeLessThanOrEqual(bound);
      expect(chunks.every((c) => c.length > 0)).toBe(true);
      expect(chunks.length).toBe(bound >= whole.length ? 1 : chunks.length);
      expect(chunks.length).toBeGreaterThanOrEqual(Math.ceil(whole.length / bound));
    }
  });

  it('hands each piece over as it is written, in order', () => {
    const seen: string[] = [];
    const decoder = new TextDecoder();
    writeMesh(big, 'off', (chunk) => seen.push(decoder.decode(chunk)), 4096);
    expect(seen.length).toBeGreaterThan(100);
    expect(seen.join('')).toBe(exportMesh(big, 'off'));
    expect(seen[0].startsWith(`OFF\n${big.positions.length / 3} ${big.faceSizes.length} 0\n`)).toBe(true);
  });

  it('stops at an error thrown by the receiver and rethrows it; the module goes on', () => {
    let calls = 0;
    const failure = new Error('disk full');
    expect(() =>
      writeMesh(
        big,
        'obj',
        () => {
          calls += 1;
          if (calls === 3) throw failure;
        },
        1000,
      ),
    ).toThrow(failure);
    expect(calls).toBe(3);
    expect(meshFacts(parseMesh(exportMesh(big, 'obj'), 'obj')).faces).toBe(big.faceSizes.length);
  });

  it.each([0, 63, 1.5, 2 ** 28 + 1, Number.NaN])('refuses chunkBytes %d', (bound) => {
    let error: unknown = null;
    try {
      exportMeshChunks(big, 'off', bound);
    } catch (e) {
      error = e;
    }
    expect(error).toBeInstanceOf(SubdivError);
    expect((error as SubdivError).code).toBe('invalid_argument');
    expect((error as SubdivError).message).toBe(
      `chunkBytes must be a whole number from 64 to 268435456, not ${bound}.`,
    );
  });
});

describe('reading bytes', () => {
  it('parses UTF-8 bytes as it parses the string', () => {
    for (const [name, format] of [
      ['cube.obj', 'obj'],
      ['rhombicuboctahedron.off', 'off'],
    ] as const) {
      const text = fixtureText(name);
      const fromBytes = parseMesh(new TextEncoder().encode(text), format);
      const fromText = parseMesh(text, format);
      expect(Array.from(fromBytes.faceIndices)).toEqual(Array.from(fromText.faceIndices));
      expectSamePoints(fromBytes, fromText, 0);
    }
  });

  it('reports errors with their lines from bytes too', () => {
    let error: unknown = null;
    try {
      parseMesh(new TextEncoder().encode('OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 zz\n3 0 1 2\n'), 'off');
    } catch (e) {
      error = e;
    }
    expect(error).toBeInstanceOf(SubdivError);
    expect((error as SubdivError).line).toBe(5);
    expect((error as SubdivError).message).toBe("line 5: z coordinate of vertex 2 is not a number: 'zz'");
  });
});

/** parseMesh's outcome as plain data: the mesh's arrays, or the error's code, line and message. */
function outcome(input: string | Uint8Array, format: 'off' | 'obj'): unknown {
  try {
    const mesh = parseMesh(input, format);
    return { positions: Array.from(mesh.positions), faceIndices: Array.from(mesh.faceIndices) };
  } catch (e) {
    const error = e as SubdivError;
    return { code: error.code, line: error.line, message: error.message };
  }
}

describe('text into the heap (strings encoded by the engine, bytes copied by it)', () => {
  it('gives the same mesh or the same error from a string and from its bytes, on every fixture', () => {
    const names = [
      // The text formats (PLY and STL fixtures include binary files).
      ...readdirSync(FIXTURES_DIR).filter((n) => /\.(off|obj)$/.test(n)),
      ...readdirSync(join(FIXTURES_DIR, 'invalid')).map((n) => join('invalid', n)),
    ];
    expect(names.length).toBe(41);
    let errors = 0;
    for (const name of names) {
      const format = formatFromFileName(name) === 'obj' ? 'obj' : 'off';
      const text = fixtureText(name);
      const fromText = outcome(text, format);
      expect(outcome(new TextEncoder().encode(text), format), name).toEqual(fromText);
      if ('code' in (fromText as object)) errors++;
    }
    // cube-flipped-face.off and moebius.off are refused too (orientation).
    expect(errors).toBe(readdirSync(join(FIXTURES_DIR, 'invalid')).length + 2);
  });

  it('reads a string with characters beyond ASCII, and quotes them in a message on the right line', () => {
    const ok = 'OFF # caf\u00e9 \u{1F600}\n3 1 0\n0 0 0\n1 0 0 # \u00e9t\u00e9\n0 1 0\n3 0 1 2\n';
    const mesh = parseMesh(ok, 'off');
    expect(Array.from(mesh.positions)).toEqual([0, 0, 0, 1, 0, 0, 0, 1, 0]);
    expect(Array.from(mesh.faceIndices)).toEqual([0, 1, 2]);
    const bad = 'v 0 0 0 # \u00fc\nv 1 0 0\nv 0 1 \u00e9\u{1F600}\nf 1 2 3\n';
    expect(outcome(bad, 'obj')).toEqual({
      code: 'parse_error',
      line: 3,
      message: "line 3: z coordinate of vertex 3 is not a number: '\u00e9\u{1F600}'",
    });
    expect(outcome(new TextEncoder().encode(bad), 'obj')).toEqual(outcome(bad, 'obj'));
  });

  it('takes an ArrayBuffer, an empty string, and refuses what is not text', () => {
    const text = 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n';
    const bytes = new TextEncoder().encode(text);
    const copy = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
    expect(Array.from(parseMesh(copy as unknown as Uint8Array, 'off').faceIndices)).toEqual([0, 1, 2]);
    expect(outcome('', 'off')).toEqual({
      code: 'parse_error',
      line: 0,
      message: 'the file is empty: no OFF header',
    });
    expect(outcome(42 as unknown as string, 'off')).toEqual({
      code: 'invalid_argument',
      line: 0,
      message: 'The mesh text must be a string, a Uint8Array or an ArrayBuffer.',
    });
    expect(outcome(new Float64Array(3) as unknown as Uint8Array, 'off')).toMatchObject({ code: 'invalid_argument' });
  });

  it('feeds parseForView the same way', () => {
    const text = fixtureText('cube.obj');
    const fromText = parseForView(text, 'obj');
    const fromBytes = parseForView(new TextEncoder().encode(text), 'obj');
    expect(fromText.facts).toEqual(fromBytes.facts);
    expect(fromText.facts).toMatchObject({ vertices: 8, faces: 6 });
    expect(Array.from(fromText.mesh.faceIndices)).toEqual(Array.from(fromBytes.mesh.faceIndices));
  });
});
