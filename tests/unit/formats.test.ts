/**
 * PLY, STL and files that are not meshes through the real WASM core, as
 * bytes (Uint8Array, what the app's drop, ?src= and the CLI hand it):
 * counts and coordinates of the hand-made fixtures
 * (tests/fixtures/make_format_fixtures.py), the format told from the bytes
 * ('auto'), the words for a PNG, orientation repair, and PLY/STL written
 * with their comment and read back.
 */
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { beforeAll, describe, expect, it } from 'vitest';
import { initNode } from '../../web/core/init-node';
import type { MeshFormat, ReadFormat } from '../../web/core/mesh';
import { exportMeshChunks, meshFacts, parseMesh } from '../../web/core/subdiv-core';
import { SubdivError } from '../../web/core/subdiv-error';
import { FIXTURES_DIR, loadFixture } from './test-helpers';

beforeAll(async () => {
  await initNode();
});

const bytesOf = (name: string) => new Uint8Array(readFileSync(join(FIXTURES_DIR, name)));

function failure(bytes: Uint8Array, format: ReadFormat): SubdivError {
  try {
    parseMesh(bytes, format);
  } catch (error) {
    if (error instanceof SubdivError) return error;
    throw error;
  }
  throw new Error('parsed without an error');
}

function joined(chunks: Uint8Array[]): Uint8Array {
  const out = new Uint8Array(chunks.reduce((n, c) => n + c.length, 0));
  let at = 0;
  for (const c of chunks) {
    out.set(c, at);
    at += c.length;
  }
  return out;
}

describe('PLY and STL bytes', () => {
  it.each(['cube.ply', 'cube-le.ply', 'cube-be.ply'])('%s is cube.off exactly, as ply and as auto', (name) => {
    const cube = () => loadFixture('cube.off');
    for (const format of ['ply', 'auto'] as const) {
      const mesh = parseMesh(bytesOf(name), format);
      expect(Array.from(mesh.positions)).toEqual(Array.from(cube().positions));
      expect(Array.from(mesh.faceSizes)).toEqual([4, 4, 4, 4, 4, 4]);
      expect(Array.from(mesh.faceIndices)).toEqual(Array.from(cube().faceIndices));
    }
  });

  it.each(['tetrahedron.stl', 'tetrahedron-binary.stl'])('%s welds 12 corners into 4 vertices', (name) => {
    for (const format of ['stl', 'auto'] as const) {
      const mesh = parseMesh(bytesOf(name), format);
      // (0,0,0), (0,1,0), (1,0,0), (0,0,1): the order the corners come in.
      expect(Array.from(mesh.positions)).toEqual([0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1]);
      expect(meshFacts(mesh)).toMatchObject({ vertices: 4, edges: 6, faces: 4, triangles: 4, closed: true, genus: 0 });
    }
  });

  it('a PNG says what it is, whatever format it was given as', () => {
    for (const format of ['auto', 'off', 'obj', 'ply', 'stl'] as const) {
      const error = failure(bytesOf('not-a-mesh.png'), format);
      expect(error.code).toBe('parse_error');
      expect(error.message).toBe('This is a PNG image, not a mesh. SubdivLab reads OFF, OBJ, PLY and STL.');
    }
  });

  it('a binary file, or a mesh of another format, is named, its bytes not quoted', () => {
    // Every byte value once: 28 control bytes and 128 in no UTF-8 sequence.
    const all = Uint8Array.from({ length: 256 }, (_, i) => i);
    expect(failure(all, 'off').message).toBe(
      'This looks like a binary file, not OFF text: 156 of its first 256 bytes are control bytes or no UTF-8 text. SubdivLab reads OFF, OBJ, PLY and STL.',
    );
    expect(failure(bytesOf('tetrahedron-binary.stl'), 'off').message).toBe(
      'This looks like a binary STL file, not OFF text: give it the .stl extension to read it as STL.',
    );
    expect(failure(bytesOf('cube-le.ply'), 'obj').message).toBe(
      'This looks like a PLY file, not OBJ: give it the .ply extension to read it as PLY.',
    );
    // Text with one stray byte is quoted, the byte as \xNN.
    const stray = new TextEncoder().encode('OFF\n3 1 0\n0 0 #z\n1 0 0\n0 1 0\n3 0 1 2\n');
    stray[stray.indexOf(35)] = 0xff;
    const error = failure(stray, 'off');
    expect(error.line).toBe(3);
    expect(error.message).toBe("line 3: z coordinate of vertex 0 is not a number: '\\xFFz'");
  });

  it('a binary PLY cut short names the byte and the face', () => {
    const le = bytesOf('cube-le.ply');
    const error = failure(le.subarray(0, le.length - 40), 'ply');
    expect(error.code).toBe('parse_error');
    expect(error.line).toBe(0);
    expect(error.message).toMatch(/^byte \d+: .* of face 4 \(of 6\)/);
  });
});

describe('orientation', () => {
  it('one flipped face: inconsistent_orientation, then repaired on request', () => {
    const bytes = bytesOf('cube-flipped-face.off');
    const error = failure(bytes, 'off');
    expect(error.code).toBe('inconsistent_orientation');
    expect(error.message).toContain('turning 1 face around makes them agree');
    const repaired = parseMesh(bytes, 'off', { repairOrientation: true });
    expect(Array.from(repaired.faceIndices)).toEqual(Array.from(loadFixture('cube.off').faceIndices));
    expect(repaired.tags?.notes).toEqual(['orientation repaired: 1 face was reversed to agree with their neighbours']);
  });

  it('a Möbius strip is non-orientable, repair or not', () => {
    for (const repairOrientation of [false, true]) {
      try {
        parseMesh(bytesOf('moebius.off'), 'off', { repairOrientation });
        throw new Error('parsed');
      } catch (error) {
        expect((error as SubdivError).code).toBe('invalid_mesh');
        expect((error as SubdivError).message).toMatch(
          /^line 18: the surface is non-orientable \(like a Möbius strip\)/,
        );
      }
    }
  });
});

describe('writing PLY and STL', () => {
  const cube = () => loadFixture('cube.off');
  const comment = 'SubdivLab: cube.off, Catmull-Clark, level 0';

  it('PLY: ASCII with the comment in its header, read back exactly', () => {
    const bytes = joined(exportMeshChunks(cube(), 'ply', 64, comment));
    const text = new TextDecoder().decode(bytes);
    expect(text.split('\n').slice(0, 4)).toEqual(['ply', 'format ascii 1.0', `comment ${comment}`, 'element vertex 8']);
    const back = parseMesh(bytes, 'auto');
    expect(Array.from(back.positions)).toEqual(Array.from(cube().positions));
    expect(Array.from(back.faceIndices)).toEqual(Array.from(cube().faceIndices));
  });

  it('STL: 84 + 50 × 12 bytes (6 quads as 12 triangles), the comment as header, 8 welded vertices back', () => {
    const bytes = joined(exportMeshChunks(cube(), 'stl', 64, comment));
    expect(bytes.length).toBe(84 + 50 * 12);
    expect(new TextDecoder().decode(bytes.subarray(0, comment.length))).toBe(comment);
    const view = new DataView(bytes.buffer, bytes.byteOffset);
    expect(view.getUint32(80, true)).toBe(12);
    // The first facet's normal: face 1 0 2 3 lies in z = −1, facing −z.
    expect([view.getFloat32(84, true), view.getFloat32(88, true), view.getFloat32(92, true)]).toEqual([0, 0, -1]);
    const back = parseMesh(bytes, 'auto');
    expect(meshFacts(back)).toMatchObject({ vertices: 8, edges: 18, faces: 12, triangles: 12, genus: 0 });
  });

  it.each<MeshFormat>(['off', 'obj'])('%s carries the comment as a # line the reader skips', (format) => {
    const text = new TextDecoder().decode(joined(exportMeshChunks(cube(), format, undefined, comment)));
    expect(text.split('\n')).toContain(`# ${comment}`);
    expect(Array.from(parseMesh(text, format).positions)).toEqual(Array.from(cube().positions));
  });
});
