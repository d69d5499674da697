/**
 * Check a result names a student's vertices by their line and their number
 * in the file (web/core/vertex-lines.ts): exact lines in OFF and OBJ files
 * with comments, blank lines, CRLF and lone CR line ends, counts on the
 * header's line, OBJ continuations and negative indices, and a vertex no
 * face uses (the core drops it, so the mesh's numbers shift past it). Each
 * line found is checked against the core's own reading: the numbers on that
 * line are the mesh vertex's coordinates.
 */
import { beforeAll, describe, expect, it } from 'vitest';
import { initNode } from '../../web/core/init-node';
import type { ReadFormat } from '../../web/core/mesh';
import { parseMesh } from '../../web/core/subdiv-core';
import { vertexName, vertexSources } from '../../web/core/vertex-lines';

beforeAll(async () => {
  await initNode();
});

/** Every mesh vertex's coordinates are the first three numbers of its line (after "v" in OBJ). */
function expectLinesHoldTheVertices(text: string, format: ReadFormat): void {
  const mesh = parseMesh(text, format);
  const sources = vertexSources(text, format);
  expect(sources?.vertices).toHaveLength(mesh.positions.length / 3);
  const lines = text.split(/\r\n|\r|\n/);
  sources?.vertices.forEach(({ line }, v) => {
    const numbers = lines[line - 1]
      .replace(/^\s*v\s/, '')
      .trim()
      .split(/\s+/)
      .slice(0, 3)
      .map(Number);
    expect(numbers, `vertex ${v} on line ${line}`).toEqual(Array.from(mesh.positions.subarray(3 * v, 3 * v + 3)));
  });
}

describe('OFF', () => {
  // Comments, blank lines and a comment after data; the counts on the header's line.
  const text = [
    '# a tetrahedron', // 1
    '', // 2
    'OFF 4 4 6', // 3
    '# its corners', // 4
    '0 0 0', // 5  vertex 0
    '', // 6
    '1 0 0 # x', // 7  vertex 1
    '   # indented comment', // 8
    '0 1 0', // 9  vertex 2
    '0 0 1', // 10 vertex 3
    '3 0 2 1',
    '3 0 1 3',
    '3 0 3 2',
    '3 1 2 3',
    '',
  ].join('\n');

  it('gives each vertex its line, counting from 0 as OFF does', () => {
    expect(vertexSources(text, 'off')).toEqual({
      format: 'off',
      vertices: [
        { line: 5, fileVertex: 0 },
        { line: 7, fileVertex: 1 },
        { line: 9, fileVertex: 2 },
        { line: 10, fileVertex: 3 },
      ],
    });
    expectLinesHoldTheVertices(text, 'off');
    expect(vertexSources(text, 'auto')?.vertices[3]).toEqual({ line: 10, fileVertex: 3 });
  });

  it('counts CRLF and lone CR line ends as the reader does, and reads bytes', () => {
    const crlf = text.replaceAll('\n', '\r\n');
    expect(vertexSources(crlf, 'off')?.vertices.map((s) => s.line)).toEqual([5, 7, 9, 10]);
    const cr = text.replaceAll('\n', '\r');
    expect(vertexSources(new TextEncoder().encode(cr), 'off')?.vertices.map((s) => s.line)).toEqual([5, 7, 9, 10]);
    expectLinesHoldTheVertices(crlf, 'off');
  });

  it('skips a vertex no face uses: the mesh numbers past it shift, the file numbers do not', () => {
    const withUnused = 'OFF\n5 4 0\n0 0 0\n9 9 9\n1 0 0\n0 1 0\n0 0 1\n3 0 3 2\n3 0 2 4\n3 0 4 3\n3 2 3 4\n';
    const sources = vertexSources(withUnused, 'off');
    expect(sources?.vertices).toEqual([
      { line: 3, fileVertex: 0 },
      { line: 5, fileVertex: 2 },
      { line: 6, fileVertex: 3 },
      { line: 7, fileVertex: 4 },
    ]);
    expectLinesHoldTheVertices(withUnused, 'off');
    expect(vertexName({ vertex: 1, ...sources?.vertices[1] }, sources?.format)).toBe('vertex 2 (line 5)');
  });
});

describe('OBJ', () => {
  const text = [
    '# exported by my program', // 1
    'mtllib house.mtl', // 2
    'o tetra', // 3
    'v 0 0 0', // 4  v 1
    '', // 5
    'vn 0 0 1', // 6
    'v 1 0 0 # second', // 7  v 2
    'v \\', // 8  v 3, continued
    '  0 1 0', // 9
    '# a comment', // 10
    'v 0 0 1', // 11 v 4
    'v 5 5 5', // 12 v 5, no face uses it
    'vt 0 0', // 13
    'f 1 3 2', // 14
    'f 1/1 2/1 4/1', // 15
    'f -5 -2 -3', // 16: v 1, v 4, v 3
    'f 2//1 3//1 \\', // 17
    '4//1', // 18
    '',
  ].join('\n');

  it('gives each "v" statement its first line and its OBJ number, leaving out the one no face uses', () => {
    const sources = vertexSources(text, 'obj');
    expect(sources).toEqual({
      format: 'obj',
      vertices: [
        { line: 4, fileVertex: 0 },
        { line: 7, fileVertex: 1 },
        { line: 8, fileVertex: 2 },
        { line: 11, fileVertex: 3 },
      ],
    });
    expect(parseMesh(text, 'obj').positions).toEqual(new Float64Array([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1]));
    expect(vertexName({ vertex: 2, ...sources?.vertices[2] }, sources?.format)).toBe('vertex 2 (line 8, OBJ v 3)');
    expect(vertexName({ vertex: 3, ...sources?.vertices[3] }, sources?.format)).toBe('vertex 3 (line 11, OBJ v 4)');
    expect(vertexSources(text, 'auto')?.format).toBe('obj');
  });

  it('a face written before the vertices it names: they are used, and keep their lines', () => {
    const early = ['# faces first', 'f 1 2 3', 'f 1 3 4', 'v 0 0 0', 'v 1 0 0', 'v 0 1 0', 'v 0 0 1', ''].join('\n');
    expect(vertexSources(early, 'obj')?.vertices).toEqual([
      { line: 4, fileVertex: 0 },
      { line: 5, fileVertex: 1 },
      { line: 6, fileVertex: 2 },
      { line: 7, fileVertex: 3 },
    ]);
    expectLinesHoldTheVertices(early, 'obj');
  });

  it('course.obj (every form at once, CRLF): each line holds its vertex', async () => {
    const { readFileSync } = await import('node:fs');
    const course = readFileSync('tests/fixtures/course.obj', 'utf8');
    const sources = vertexSources(course, 'obj');
    expect(sources?.vertices.length).toBe(parseMesh(course, 'obj').positions.length / 3);
    const mesh = parseMesh(course, 'obj');
    const lines = course.split(/\r\n|\r|\n/);
    sources?.vertices.forEach(({ line }, v) => {
      // A "v" statement may run on over lines: its numbers are those of the joined lines.
      let joined = '';
      for (let l = line - 1; ; ++l) {
        const data = lines[l].split('#')[0];
        joined += ` ${data.replace(/\\\s*$/, ' ')}`;
        if (!/\\\s*$/.test(data)) break;
      }
      const numbers = joined.trim().split(/\s+/).slice(1, 4).map(Number);
      expect(numbers, `vertex ${v} on line ${line}`).toEqual(Array.from(mesh.positions.subarray(3 * v, 3 * v + 3)));
    });
  });
});

describe('other formats', () => {
  it('PLY and STL have no vertex lines: plain numbers', () => {
    expect(vertexSources('ply\n', 'ply')).toBeNull();
    expect(vertexSources('solid x\n', 'stl')).toBeNull();
    expect(vertexName({ vertex: 7 }, undefined)).toBe('vertex 7');
  });
});
