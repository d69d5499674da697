/** The subdiv CLI on PLY, STL, a PNG and orientation, as a user runs it: node bin/subdiv.mjs. */
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { beforeAll, describe, expect, it } from 'vitest';
import { initNode } from '../../web/core/init-node';
import { meshFacts, parseMesh } from '../../web/core/subdiv-core';
import { FIXTURES_DIR } from './test-helpers';

const ROOT = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
const BIN = join(ROOT, 'bin', 'subdiv.mjs');

function subdiv(args: string[]) {
  const r = spawnSync(process.execPath, [BIN, ...args], { cwd: ROOT, encoding: 'utf8' });
  return { status: r.status, stdout: r.stdout, stderr: r.stderr };
}

const fixture = (name: string) => join(FIXTURES_DIR, name);
let work = '';

beforeAll(async () => {
  await initNode();
  work = mkdtempSync(join(tmpdir(), 'subdiv-formats-'));
});

describe('subdiv on PLY and STL', () => {
  it.each([
    ['cube-be.ply', 'vertices: 8\nedges: 12\nfaces: 6 (0 triangles, 6 quads, 0 other)'],
    ['tetrahedron-binary.stl', 'vertices: 4\nedges: 6\nfaces: 4 (4 triangles, 0 quads, 0 other)'],
  ])('info %s', (name, counts) => {
    const r = subdiv(['info', fixture(name)]);
    expect(r.stderr).toBe('');
    expect(r.status).toBe(0);
    expect(r.stdout.startsWith(counts)).toBe(true);
  });

  it('-o .stl and -o .ply write files that read back, with the comment naming input, scheme and level', () => {
    const stl = join(work, 'cube.stl');
    expect(subdiv([fixture('cube.ply'), '--levels', '1', '-o', stl]).status).toBe(0);
    const bytes = new Uint8Array(readFileSync(stl));
    // Catmull-Clark level 1 of the cube: 24 quads, 48 triangles in STL.
    expect(bytes.length).toBe(84 + 50 * 48);
    expect(new TextDecoder().decode(bytes.subarray(0, 40))).toBe('SubdivLab: cube.ply, Catmull-Clark, leve');
    expect(meshFacts(parseMesh(bytes, 'stl'))).toMatchObject({ vertices: 26, faces: 48, genus: 0 });
    const ply = join(work, 'tetra.ply');
    expect(subdiv([fixture('tetrahedron.stl'), '--scheme', 'loop', '--levels', '2', '-o', ply]).status).toBe(0);
    const text = readFileSync(ply, 'utf8');
    expect(text.split('\n')[2]).toBe('comment SubdivLab: tetrahedron.stl, Loop, level 2');
    expect(meshFacts(parseMesh(text, 'ply'))).toMatchObject({ vertices: 34, faces: 64 });
    const off = join(work, 'tetra.off');
    expect(subdiv([ply, '--levels', '0', '-o', off]).status).toBe(0);
    expect(readFileSync(off, 'utf8').split('\n').slice(0, 2)).toEqual([
      'OFF',
      '# SubdivLab: tetra.ply, Catmull-Clark, level 0',
    ]);
  });

  it('a PNG: one error line saying what it is', () => {
    const r = subdiv(['info', fixture('not-a-mesh.png')]);
    expect(r.status).toBe(1);
    expect(r.stdout).toBe('');
    expect(r.stderr).toBe(
      `error: ${fixture('not-a-mesh.png')}: This is a PNG image, not a mesh. SubdivLab reads OFF, OBJ, PLY and STL.\n`,
    );
  });

  it('--repair-orientation turns the flipped face; a Möbius strip is still refused', () => {
    const flipped = fixture('cube-flipped-face.off');
    const refused = subdiv(['info', flipped]);
    expect(refused.status).toBe(1);
    expect(refused.stderr).toContain('turning 1 face around makes them agree (repair orientation)');
    const repaired = subdiv(['info', flipped, '--repair-orientation']);
    expect(repaired.status).toBe(0);
    expect(repaired.stdout).toContain('genus: 0\nclosed: yes');
    expect(repaired.stdout).toContain('note: orientation repaired: 1 face was reversed to agree with their neighbours');
    const moebius = subdiv([fixture('moebius.off'), '--repair-orientation', '--levels', '0', '--stats']);
    expect(moebius.status).toBe(1);
    expect(moebius.stderr).toMatch(/line 18: the surface is non-orientable \(like a Möbius strip\)/);
  });
});
