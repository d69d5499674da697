/**
 * Where each vertex of a mesh read from OFF or OBJ text stands in its file:
 * the line it is on and its number among the file's vertices, so that a
 * message names a student's vertex as their file has it ("vertex 7 (line
 * 12, OBJ v 8)": OFF counts vertices from 0, OBJ from 1). The core's reader
 * (wasm/src/core/mesh_io.cpp) keeps no lines for vertices and drops those
 * no face uses, numbering the rest from 0; this reads the text the way it
 * does: lines end at \n, \r\n or a lone \r, lines of blanks and comments are
 * skipped, OFF has one vertex a line after its counts (on the header's line
 * or the next), an OBJ statement runs on over lines that end in a backslash
 * and is named by its first line, and only the vertices that faces use (OBJ:
 * by 1-based or negative indices) are kept, in file order.
 */
import type { ReadFormat } from './mesh';

/** A mesh vertex in its file: the 1-based line, and its 0-based number among the file's vertices. */
export interface VertexSource {
  line: number;
  fileVertex: number;
}

/** The file's vertex numbers as its format counts them: OFF from 0, OBJ from 1. */
export interface VertexSources {
  format: 'off' | 'obj';
  vertices: VertexSource[];
}

/** A statement: its first line (1-based) and its tokens, comments left out. */
interface Statement {
  line: number;
  tokens: string[];
}

const BLANKS = /[ \t\v\f]+/;

function tokensOf(content: string): string[] {
  const hash = content.indexOf('#');
  return (hash >= 0 ? content.slice(0, hash) : content).split(BLANKS).filter((t) => t !== '');
}

/** The data lines of `lines` in order (with `continued`, OBJ's backslash joining the next line). */
function* statements(lines: readonly string[], continued: boolean): Generator<Statement> {
  for (let i = 0; i < lines.length; ++i) {
    const line = i + 1;
    const start = lines[i].replace(/^[ \t\v\f]+/, '');
    if (start === '' || start[0] === '#') continue;
    const tokens: string[] = [];
    let content = lines[i];
    for (;;) {
      const hash = content.indexOf('#');
      let data = hash >= 0 ? content.slice(0, hash) : content;
      const more = continued && /\\[ \t\v\f]*$/.test(data);
      if (more) data = data.replace(/\\[ \t\v\f]*$/, '');
      tokens.push(...tokensOf(data));
      if (!more || i + 1 >= lines.length) break;
      content = lines[++i];
    }
    yield { line, tokens };
  }
}

/** The vertex lines of an OFF file and the vertices its faces use; null if it is not OFF as the reader takes it. */
function offVertices(lines: readonly string[]): { lines: number[]; used: boolean[] } | null {
  const it = statements(lines, false);
  const header = it.next().value;
  // [ST][C][N][4]OFF; nOFF's dimension line is not followed here.
  if (!header || !/^(ST)?C?N?4?OFF$/.test(header.tokens[0])) return null;
  const counts = header.tokens.length > 1 ? header.tokens.slice(1) : it.next().value?.tokens;
  const nv = Number(counts?.[0]);
  const nf = Number(counts?.[1]);
  if (!Number.isInteger(nv) || !Number.isInteger(nf)) return null;
  const vertexLines: number[] = [];
  for (let v = 0; v < nv; ++v) {
    const s = it.next().value;
    if (!s) return null;
    vertexLines.push(s.line);
  }
  const used = new Array<boolean>(nv).fill(false);
  for (let f = 0; f < nf; ++f) {
    const s = it.next().value;
    if (!s) return null;
    const k = Number(s.tokens[0]);
    for (let j = 1; j <= k; ++j) used[Number(s.tokens[j])] = true;
  }
  return { lines: vertexLines, used };
}

/** The lines of an OBJ file's "v" statements and the vertices its faces use. */
function objVertices(lines: readonly string[]): { lines: number[]; used: boolean[] } {
  const vertexLines: number[] = [];
  // The vertices faces name, known once every "v" is read: a positive index may name one further down.
  const named: number[] = [];
  for (const s of statements(lines, true)) {
    if (s.tokens[0] === 'v') {
      vertexLines.push(s.line);
    } else if (s.tokens[0] === 'f') {
      for (const corner of s.tokens.slice(1)) {
        const i = Number.parseInt(corner, 10);
        // Negative: counted back from the last vertex so far.
        named.push(i < 0 ? vertexLines.length + i : i - 1);
      }
    }
  }
  const used = new Array<boolean>(vertexLines.length).fill(false);
  for (const v of named) if (v >= 0 && v < used.length) used[v] = true;
  return { lines: vertexLines, used };
}

/** The format of text given as 'auto': OFF by its header keyword, OBJ by a "v" or "f" statement first. */
function sniff(lines: readonly string[]): 'off' | 'obj' | null {
  const first = statements(lines, false).next().value?.tokens[0] ?? '';
  if (/OFF$/.test(first)) return 'off';
  return ['v', 'vn', 'vt', 'f', 'o', 'g', 's', 'mtllib', 'usemtl'].includes(first) ? 'obj' : null;
}

/**
 * Where the vertices of the mesh the core reads from `text` stand in the
 * file, vertex i of the mesh first; null for PLY and STL (binary, or
 * corners welded into vertices) and for text that is neither OFF nor OBJ.
 * Precondition: the core read `text` as `format` without an error.
 */
export function vertexSources(text: string | Uint8Array, format: ReadFormat): VertexSources | null {
  if (format === 'ply' || format === 'stl') return null;
  const decoded = typeof text === 'string' ? text : new TextDecoder().decode(text);
  const lines = decoded.replace(/^\uFEFF/, '').split(/\r\n|\r|\n/);
  const kind = format === 'auto' ? sniff(lines) : format;
  if (!kind) return null;
  const found = kind === 'off' ? offVertices(lines) : objVertices(lines);
  if (!found) return null;
  const vertices: VertexSource[] = [];
  found.used.forEach((used, v) => {
    if (used) vertices.push({ line: found.lines[v], fileVertex: v });
  });
  return { format: kind, vertices };
}

/**
 * How a message names a result's vertex: by its number in the file and its
 * line when they are known (`vertex`: the mesh's number, `line` and
 * `fileVertex` from {@link vertexSources}), "vertex 7 (line 12)" in OFF,
 * "vertex 7 (line 12, OBJ v 8)" in OBJ; else "vertex 7".
 */
export function vertexName(
  w: { vertex: number; line?: number; fileVertex?: number },
  format: 'off' | 'obj' | undefined,
): string {
  if (w.line === undefined || w.fileVertex === undefined || !format) return `vertex ${w.vertex}`;
  const obj = format === 'obj' ? `, OBJ v ${w.fileVertex + 1}` : '';
  return `vertex ${w.fileVertex} (line ${w.line}${obj})`;
}
