/** The subdiv CLI as a user runs it: node bin/subdiv.mjs (bundle built by setup). */
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { beforeAll, describe, expect, it } from 'vitest';
import { initNode } from '../../web/core/init-node';
import { meshFacts, parseMesh } from '../../web/core/subdiv-core';
import { FIXTURES_DIR } from './test-helpers';

const ROOT = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
const BIN = join(ROOT, 'bin', 'subdiv.mjs');

function subdiv(args: string[], cwd = ROOT) {
  const r = spawnSync(process.execPath, [BIN, ...args], { cwd, encoding: 'utf8' });
  return { status: r.status, stdout: r.stdout, stderr: r.stderr };
}

const fixture = (name: string) => join(FIXTURES_DIR, name);
let work = '';

beforeAll(async () => {
  await initNode();
  work = mkdtempSync(join(tmpdir(), 'subdiv-cli-'));
});

describe('subdiv CLI', () => {
  it('--stats prints one JSON object with the exact facts', () => {
    const r = subdiv([fixture('torus-quad.off'), '--levels', '2', '--stats']);
    expect(r.stderr).toBe('');
    expect(r.status).toBe(0);
    const lines = r.stdout.trim().split('\n');
    expect(lines).toHaveLength(1);
    const stats = JSON.parse(lines[0]);
    expect(Object.keys(stats)).toEqual([
      'vertices',
      'edges',
      'faces',
      'components',
      'boundaries',
      'eulerCharacteristic',
      'genus',
      'closed',
      'triangles',
      'quads',
      'otherFaces',
      'controlEdges',
      'ms',
    ]);
    const { ms, ...counts } = stats;
    // 48 quads → 192 → 768 faces; V = 768, E = 1536 (χ = 0).
    expect(counts).toEqual({
      vertices: 768,
      edges: 1536,
      faces: 768,
      components: 1,
      boundaries: 0,
      eulerCharacteristic: 0,
      genus: 1,
      closed: true,
      triangles: 0,
      quads: 768,
      otherFaces: 0,
      controlEdges: 384, // the 96 control edges, each split in 4
    });
    expect(typeof ms).toBe('number');
    expect(ms).toBeGreaterThanOrEqual(0);
  });

  it('defaults to one level of catmull-clark and accepts every scheme', () => {
    const r = subdiv([fixture('cube.off'), '--stats']);
    expect(JSON.parse(r.stdout)).toMatchObject({ vertices: 26, edges: 48, faces: 24 });
    const loop = subdiv([fixture('icosahedron.off'), '--scheme', 'loop', '--stats']);
    expect(JSON.parse(loop.stdout)).toMatchObject({ vertices: 42, faces: 80, triangles: 80 });
    const ds = subdiv([fixture('cube.off'), '--scheme', 'doo-sabin', '--stats']);
    expect(JSON.parse(ds.stdout)).toMatchObject({ vertices: 24, faces: 26, quads: 18, triangles: 8 });
    const s3 = subdiv([fixture('cube.off'), '--scheme', 'sqrt3', '--triangulate', '--stats']);
    expect(s3.status).toBe(0);
    expect(JSON.parse(s3.stdout)).toMatchObject({ vertices: 8 + 12, faces: 36, triangles: 36 });
  });

  it('--levels 0 loads, checks and converts', () => {
    const out = join(work, 'cube-copy.obj');
    const r = subdiv([fixture('cube.off'), '--levels', '0', '-o', out, '--stats']);
    expect(r.status).toBe(0);
    expect(JSON.parse(r.stdout)).toMatchObject({ vertices: 8, edges: 12, faces: 6 });
    expect(meshFacts(parseMesh(readFileSync(out, 'utf8'), 'obj'))).toMatchObject({ vertices: 8, faces: 6, quads: 6 });
  });

  it('-o out.obj writes a file that parses back to the same counts', () => {
    const out = join(work, 'out.obj');
    const r = subdiv([fixture('mixed-open.off'), '--levels', '2', '-o', out]);
    expect(r.status).toBe(0);
    expect(r.stdout).toBe('');
    const facts = meshFacts(parseMesh(readFileSync(out, 'utf8'), 'obj'));
    // Σ degrees of mixed-open = 2·4 + 6·3 + 5 = 31 quads at level 1, ×4 at level 2.
    expect(facts).toMatchObject({ faces: 124, quads: 124, boundaries: 1, genus: 0 });
    const off = join(work, 'out.off');
    expect(subdiv([out, '--levels', '0', '-o', off]).status).toBe(0);
    expect(meshFacts(parseMesh(readFileSync(off, 'utf8'), 'off'))).toEqual(facts);
  });

  it('without -o or --stats writes OFF to stdout', () => {
    const r = subdiv([fixture('tetrahedron.off'), '--scheme', 'loop']);
    expect(r.status).toBe(0);
    expect(meshFacts(parseMesh(r.stdout, 'off'))).toMatchObject({ vertices: 10, faces: 16 });
  });

  it('bad input: exit 1 and one error line naming the file and the line', () => {
    const bad = join(work, 'bad.off');
    writeFileSync(
      bad,
      'OFF\n8 6 0\n-1 -1 -1\n1 -1 -1\n1 1 -1\n-1 1 -1\n-1 -1 1\n1 -1 1\n1 1 1\n-1 1 1\n4 0 3 2 1\n4 4 5 6 12\n',
    );
    const r = subdiv(['bad.off'], work);
    expect(r.status).toBe(1);
    expect(r.stdout).toBe('');
    expect(r.stderr).toBe('error: bad.off: line 12: face index 12 is out of range (8 vertices)\n');
  });

  it('bad input without a line, a missing file, and triangles needed: exit 1', () => {
    const missing = subdiv(['nowhere.off'], work);
    expect(missing.status).toBe(1);
    expect(missing.stderr).toMatch(/^error: nowhere\.off: cannot read: no such file\n$/);
    const quads = subdiv([fixture('cube.off'), '--scheme', 'loop']);
    expect(quads.status).toBe(1);
    expect(quads.stderr.split('\n')).toHaveLength(2);
    expect(quads.stderr).toMatch(/^error: .*cube\.off: .*loop.*6/);
  });

  it.each([
    [[]],
    [['a.off', 'b.off']],
    [[fixture('cube.off'), '--levels', '-1']],
    [[fixture('cube.off'), '--levels', 'two']],
    [[fixture('cube.off'), '--scheme', 'butterfly']],
    [[fixture('cube.off'), '--frobnicate']],
    [[fixture('cube.off'), '-o', join(work || tmpdir(), 'x.fbx')]],
  ])('bad usage %j: exit 2 with the usage', (args) => {
    const r = subdiv(args);
    expect(r.status).toBe(2);
    expect(r.stdout).toBe('');
    expect(r.stderr).toContain(
      'usage: subdiv INPUT [--scheme S] [--levels N] [--triangulate] [-o OUTPUT.off|.obj|.ply|.stl] [--stats]',
    );
  });

  it('info prints the facts, the tag counts, the border mode, the crease method and the notes', () => {
    const r = subdiv(['info', fixture('cube-creased.obj')]);
    expect(r.stderr).toBe('');
    expect(r.status).toBe(0);
    expect(r.stdout).toBe(
      [
        'vertices: 8',
        'edges: 12',
        'faces: 6 (0 triangles, 6 quads, 0 other)',
        'components: 1',
        'boundaries: 0',
        'genus: 0',
        'closed: yes',
        'creases: 4',
        'corners: 1',
        'holes: 0',
        'boundary: edge (from the file)',
        'crease method: uniform',
        '',
      ].join('\n'),
    );
    const noted = join(work, 'noted.obj');
    writeFileSync(noted, `${readFileSync(fixture('tetra-crease.obj'), 'utf8')}t smoothtriangles 1/0/0 1\n`);
    const n = subdiv(['info', noted]);
    expect(n.status).toBe(0);
    expect(n.stdout).toContain(
      'creases: 1\ncorners: 0\nholes: 0\nboundary: edge\ncrease method: chaikin (from the file)\n',
    );
    expect(n.stdout.endsWith("note: line 13: tag 'smoothtriangles' is not applied\n")).toBe(true);
    const holed = subdiv(['info', fixture('torus-holed.obj')]);
    expect(holed.stdout).toContain('holes: 2\n');
  });

  it('info on a bad tag: exit 1 with the file and the line', () => {
    const bad = join(work, 'bad-tag.obj');
    writeFileSync(bad, `${readFileSync(fixture('tetra-crease.obj'), 'utf8')}t crease 2/1/0 0 9 1\n`);
    const r = subdiv(['info', bad]);
    expect(r.status).toBe(1);
    expect(r.stdout).toBe('');
    expect(r.stderr).toBe(
      `error: ${bad}: line 13: tag 'crease': vertex 9 is out of range (4 vertices; tag indices start at 0)\n`,
    );
  });

  it('--crease-method and --boundary are taken for subdividing; tags survive --levels 0', () => {
    const r = subdiv([fixture('cube-creased.obj'), '--crease-method', 'chaikin', '--boundary', 'none', '--stats']);
    expect(r.stderr).toBe('');
    expect(r.status).toBe(0);
    expect(JSON.parse(r.stdout).faces).toBe(24);
    // The 3 x 3 patch's file says interpolateboundary 1 (edge and corner); --boundary none
    // overrides it: the 8 faces at the border become holes, so their 32 children are, and
    // the result says which mode made it.
    const file = join(work, 'file-mode.obj');
    const none = join(work, 'none.obj');
    expect(subdiv([fixture('quad-patch-corners.obj'), '-o', file]).status).toBe(0);
    expect(subdiv([fixture('quad-patch-corners.obj'), '--boundary', 'none', '-o', none]).status).toBe(0);
    const a = parseMesh(readFileSync(file, 'utf8'), 'obj');
    const b = parseMesh(readFileSync(none, 'utf8'), 'obj');
    expect(a.tags?.boundary).toBe('edge-and-corner');
    expect(a.tags?.holes.length).toBe(0);
    expect(b.tags?.boundary).toBe('none');
    expect(b.tags?.holes.length).toBe(32);
    const out = join(work, 'creased.off');
    const converted = subdiv([fixture('cube-creased.obj'), '--levels', '0', '-o', out]);
    expect(converted.status).toBe(0);
    const text = readFileSync(out, 'utf8');
    expect(text).toContain('# t crease 2/1/0 4 5 2\n');
    expect(text).toContain('# t interpolateboundary 1/0/0 2\n');
    expect(parseMesh(text, 'off').tags?.cornerVertices).toEqual(new Uint32Array([6]));
  });

  it.each([
    [['info']],
    [['info', 'a.obj', 'b.obj']],
    [['info', 'a.obj', '--levels', '2']],
    [[fixture('cube.off'), '--crease-method', 'smooth']],
    [[fixture('cube.off'), '--boundary', 'edges']],
  ])('bad usage of the tag options and info %j: exit 2', (args) => {
    const r = subdiv(args);
    expect(r.status).toBe(2);
    expect(r.stderr).toContain('usage: subdiv INPUT');
  });

  it('--help prints the usage on stdout, exit 0', () => {
    const r = subdiv(['--help']);
    expect(r.status).toBe(0);
    expect(r.stdout).toContain('usage: subdiv INPUT');
  });
});
