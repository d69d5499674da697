/**
 * OBJ as course files write it (issue 12), through the WASM core and the
 * CLI: tests/fixtures/course.obj holds every form at once (mtllib, o, g, s,
 * usemtl, v with w and with a colour, vt, vn, v/vt/vn, v//vn, v/vt, negative
 * indices, statements continued with a backslash, comments, CRLF). It is a
 * house: a 2 x 2 x 2 box with a ridge roof, counted by hand as 10 vertices,
 * 15 edges and 7 faces (5 quads, the 2 gable ends pentagons), closed, genus 0.
 */
import { spawnSync } from 'node:child_process';
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { beforeAll, describe, expect, it } from 'vitest';
import { initNode } from '../../web/core/init-node';
import { meshFacts, parseMesh } from '../../web/core/subdiv-core';
import { SubdivError } from '../../web/core/subdiv-error';
import { FIXTURES_DIR, fixtureText } from './test-helpers';

const ROOT = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
const BIN = join(ROOT, 'bin', 'subdiv.mjs');

function subdiv(args: string[]) {
  const r = spawnSync(process.execPath, [BIN, ...args], { cwd: ROOT, encoding: 'utf8' });
  return { status: r.status, stdout: r.stdout, stderr: r.stderr };
}

let work = '';

beforeAll(async () => {
  await initNode();
  work = mkdtempSync(join(tmpdir(), 'subdiv-course-'));
});

describe('OBJ as course files write it, in the WASM core', () => {
  it('reads course.obj with the counts worked out by hand, as obj and as auto', () => {
    const text = fixtureText('course.obj');
    expect(text).toContain('\\\r\n');
    for (const format of ['obj', 'auto'] as const) {
      const mesh = parseMesh(text, format);
      expect(Array.from(mesh.faceSizes)).toEqual([4, 5, 5, 4, 4, 4, 4]);
      // The faces as make_fixtures.py lists them, 0-based.
      expect(Array.from(mesh.faceIndices)).toEqual([
        0, 3, 2, 1, 0, 1, 5, 8, 4, 2, 3, 7, 9, 6, 5, 6, 9, 8, 4, 8, 9, 7, 1, 2, 6, 5, 3, 0, 4, 7,
      ]);
      // Vertex 10 (the ridge's back end) is written over two lines.
      expect(Array.from(mesh.positions.slice(24))).toEqual([1, 0, 3, 1, 2, 3]);
      expect(meshFacts(mesh)).toMatchObject({
        vertices: 10,
        edges: 15,
        faces: 7,
        triangles: 0,
        quads: 5,
        components: 1,
        boundaries: 0,
        genus: 0,
        closed: true,
      });
    }
  });

  it('names the line a refused continued statement starts on, and where it runs to', () => {
    const text = 'v 0 0 0\r\nv 1 0 0\r\nv 1 1 0\r\nf 1 2 \\\r\n  3/1/1/1\r\n';
    let error: unknown = null;
    try {
      parseMesh(text, 'obj');
    } catch (e) {
      error = e;
    }
    expect(error).toBeInstanceOf(SubdivError);
    expect((error as SubdivError).code).toBe('parse_error');
    expect((error as SubdivError).line).toBe(4);
    expect((error as SubdivError).message).toBe(
      "line 4 (continued to line 5): '3/1/1/1' is not a face vertex (expected v, v/vt, v//vn or v/vt/vn)",
    );
    // The module keeps working: the fixture still reads.
    expect(parseMesh(fixtureText('course.obj'), 'obj').faceSizes.length).toBe(7);
  });
});

describe('OBJ as course files write it, in subdiv', () => {
  it('info prints the facts of course.obj', () => {
    const r = subdiv(['info', join(FIXTURES_DIR, 'course.obj')]);
    expect(r.stderr).toBe('');
    expect(r.status).toBe(0);
    expect(r.stdout.split('\n').slice(0, 7)).toEqual([
      'vertices: 10',
      'edges: 15',
      'faces: 7 (0 triangles, 5 quads, 2 other)',
      'components: 1',
      'boundaries: 0',
      'genus: 0',
      'closed: yes',
    ]);
  });

  it('one Catmull-Clark step: V + E + F vertices, a quad per corner, 2E + corners edges', () => {
    const r = subdiv([join(FIXTURES_DIR, 'course.obj'), '--levels', '1', '--stats']);
    expect(r.stderr).toBe('');
    expect(r.status).toBe(0);
    // 10 + 15 + 7 = 32 vertices, 30 corners = 30 quads, 2 * 15 + 30 = 60 edges.
    expect(JSON.parse(r.stdout)).toMatchObject({ vertices: 32, edges: 60, faces: 30, genus: 0, closed: true });
  });

  it('refuses a continued face with a bad corner: exit 1, the file and its lines', () => {
    const bad = join(work, 'bad-continued.obj');
    writeFileSync(bad, 'v 0 0 0\nv 1 0 0\nv 1 1 0\n# a face\nf 1 \\\n 2 \\\n 3 x\n');
    const r = subdiv(['info', bad]);
    expect(r.status).toBe(1);
    expect(r.stdout).toBe('');
    expect(r.stderr).toBe(
      `error: ${bad}: line 5 (continued to line 7): 'x' is not a face vertex (expected v, v/vt, v//vn or v/vt/vn)\n`,
    );
  });
});
