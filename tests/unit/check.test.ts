/**
 * Checking a student's result (compareMeshes, `subdiv check`): a level made
 * by another implementation (reference-subdivision.ts, its own vertex order)
 * matches; a moved vertex is named by its number in the result; a level of
 * another scheme is a mismatch with its error figures.
 */
import { spawnSync } from 'node:child_process';
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { beforeAll, describe, expect, it } from 'vitest';
import { initNode } from '../../web/core/init-node';
import { compareMeshes, hausdorffDistance, subdivide } from '../../web/core/subdiv-core';
import { catmullClarkStep, loopStep, repeat } from './reference-subdivision';
import { FIXTURES_DIR, loadFixture, type PlainMesh, toPlain } from './test-helpers';

const ROOT = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
const BIN = join(ROOT, 'bin', 'subdiv.mjs');
let work = '';

beforeAll(async () => {
  await initNode();
  work = mkdtempSync(join(tmpdir(), 'subdiv-check-'));
});

/** OFF text of a plain mesh, as a student's program might write it (vertices reversed). */
function offOf(mesh: PlainMesh, reverse = true): string {
  const n = mesh.points.length;
  const at = (v: number) => (reverse ? n - 1 - v : v);
  const points = reverse ? [...mesh.points].reverse() : mesh.points;
  const lines = [`OFF`, `${n} ${mesh.faces.length} 0`, ...points.map((p) => p.join(' '))];
  for (const f of mesh.faces) lines.push(`${f.length} ${f.map(at).join(' ')}`);
  return `${lines.join('\n')}\n`;
}

function subdiv(args: string[]) {
  const r = spawnSync(process.execPath, [BIN, ...args], { cwd: ROOT, encoding: 'utf8' });
  return { status: r.status, stdout: r.stdout, stderr: r.stderr };
}

describe('compareMeshes', () => {
  it('the same level matches in order; the level before does not, by its counts', () => {
    const cube = loadFixture('cube.off');
    const core = subdivide(cube, { scheme: 'catmull-clark', levels: 2 });
    const same = compareMeshes(core, core, 1e-9);
    expect(same).toMatchObject({ match: true, matching: 'order', sameFaces: true, maxError: 0, reasons: [] });
    const before = compareMeshes(core, subdivide(cube, { scheme: 'catmull-clark', levels: 1 }), 1e-9);
    expect(before.match).toBe(false);
    expect(before.reasons.slice(0, 2)).toEqual([
      'the result has 26 vertices where the reference has 98',
      'the result has 24 faces where the reference has 96',
    ]);
  });
});

describe('subdiv check', () => {
  it('says match for a correct Catmull-Clark level made by another implementation, vertices shuffled', () => {
    const result = join(work, 'cc2.off');
    writeFileSync(result, offOf(repeat(catmullClarkStep, toPlain(loadFixture('cube.off')), 2)));
    const r = subdiv(['check', join(FIXTURES_DIR, 'cube.off'), result, '--levels', '2']);
    expect(r.stderr).toBe('');
    expect(r.status).toBe(0);
    const report = JSON.parse(r.stdout);
    expect(report).toMatchObject({
      verdict: 'match',
      reasons: [],
      reference: { vertices: 98, faces: 96 },
      result: { vertices: 98, faces: 96 },
      matching: 'nearest',
      sameFaces: true,
    });
    expect(report.maxError).toBeLessThan(1e-12);
  });

  it('names a moved vertex by its number in the result', () => {
    const loop = repeat(loopStep, toPlain(loadFixture('octahedron.off')), 2);
    // Vertex 30 of the result file (written reversed) is plain vertex n - 1 - 30.
    const n = loop.points.length;
    loop.points[n - 1 - 30] = [
      loop.points[n - 1 - 30][0] + 0.05,
      loop.points[n - 1 - 30][1],
      loop.points[n - 1 - 30][2],
    ];
    const result = join(work, 'loop2-moved.off');
    writeFileSync(result, offOf(loop));
    const r = subdiv(['check', join(FIXTURES_DIR, 'octahedron.off'), result, '--scheme', 'loop', '--levels', '2']);
    expect(r.status).toBe(1);
    expect(r.stderr).toBe('');
    const report = JSON.parse(r.stdout);
    expect(report.verdict).toBe('mismatch');
    expect(report.reasons).toEqual([`1 vertex of ${n} is farther from the reference than the tolerance`]);
    expect(report.worst[0].vertex).toBe(30);
    // After "OFF" and the counts, one vertex a line: vertex 30 on line 33.
    expect(report.worst[0].line).toBe(33);
    expect(report.worst[0].objVertex).toBeUndefined();
    expect(report.worst[0].error).toBeCloseTo(0.05, 12);
    expect(report.worst[0].got[0] - report.worst[0].expected[0]).toBeCloseTo(0.05, 12);
  });

  it('says mismatch, with the errors, for a level of another scheme', () => {
    const result = join(work, 'loop1.off');
    writeFileSync(result, offOf(repeat(loopStep, toPlain(loadFixture('octahedron.off')), 1), false));
    const r = subdiv([
      'check',
      join(FIXTURES_DIR, 'octahedron.off'),
      result,
      '--scheme',
      'linear-tri',
      '--levels',
      '1',
    ]);
    expect(r.status).toBe(1);
    const report = JSON.parse(r.stdout);
    expect(report.verdict).toBe('mismatch');
    expect(report.reasons.at(-1)).toMatch(/^\d+ vertices of 18 are farther from the reference than the tolerance$/);
    expect(report.maxError).toBeGreaterThan(0.05);
    expect(report.meanError).toBeGreaterThan(0);
    expect(report.worst).toHaveLength(5);
  });

  it('refuses bad usage and names an unreadable result', () => {
    const control = join(FIXTURES_DIR, 'cube.off');
    expect(subdiv(['check', control]).stderr).toMatch(/^subdiv: subdiv check takes two files: CONTROL RESULT\n/);
    const tol = subdiv(['check', control, control, '--tolerance=-1']);
    expect(tol.status).toBe(2);
    expect(tol.stderr).toMatch(/^subdiv: --tolerance must be a number 0 or more, not "-1"\n/);
    const missing = subdiv(['check', control, join(work, 'nothing.off')]);
    expect(missing.status).toBe(1);
    expect(missing.stderr).toBe(`error: ${join(work, 'nothing.off')}: cannot read: no such file\n`);
  });
});

describe('subdiv compare', () => {
  /** A square of side `side` at height z, as OFF. */
  const square = (z: number, side = 1) =>
    `OFF\n4 1 0\n0 0 ${z}\n${side} 0 ${z}\n${side} ${side} ${z}\n0 ${side} ${z}\n4 0 1 2 3\n`;

  it('prints the symmetric Hausdorff distance: 0.1 between parallel squares, sqrt 2 to a larger one', () => {
    const [a, b, c] = ['a.off', 'b.off', 'c.off'].map((name) => join(work, name));
    writeFileSync(a, square(0));
    writeFileSync(b, square(0.1));
    writeFileSync(c, square(0, 2));
    const parallel = subdiv(['compare', a, b]);
    expect(parallel.stderr).toBe('');
    expect(parallel.status).toBe(0);
    const report = JSON.parse(parallel.stdout);
    expect(Object.keys(report)).toEqual(['distance', 'relative', 'diagonal', 'errorBound']);
    expect(Math.abs(report.distance - 0.1)).toBeLessThanOrEqual(report.errorBound);
    expect(report.relative).toBeCloseTo(report.distance / report.diagonal, 15);
    const larger = JSON.parse(subdiv(['compare', a, c]).stdout);
    expect(Math.abs(larger.distance - Math.SQRT2)).toBeLessThanOrEqual(larger.errorBound);
  });

  it('tells Catmull-Clark and Loop apart on the cube, and refuses bad usage', () => {
    const cc = join(work, 'cube-cc3.off');
    const loop = join(work, 'cube-loop3.off');
    const cube = join(FIXTURES_DIR, 'cube.off');
    expect(subdiv([cube, '--levels', '3', '-o', cc]).status).toBe(0);
    expect(subdiv([cube, '--scheme', 'loop', '--triangulate', '--levels', '3', '-o', loop]).status).toBe(0);
    const schemes = JSON.parse(subdiv(['compare', cc, loop]).stdout);
    expect(schemes.relative).toBeGreaterThan(0.001);
    expect(JSON.parse(subdiv(['compare', cc, cc]).stdout).distance).toBeLessThan(1e-9);
    const one = subdiv(['compare', cc]);
    expect(one.status).toBe(2);
    expect(one.stderr).toMatch(/^subdiv: subdiv compare takes two files: A B\n/);
  });
});

describe('hausdorffDistance with vertex distances (side-by-side colours)', () => {
  /** A square of side `side` at height z. */
  const square = (z: number, side = 1) => ({
    positions: new Float64Array([0, 0, z, side, 0, z, side, side, z, 0, side, z]),
    faceSizes: new Uint32Array([4]),
    faceIndices: new Uint32Array([0, 1, 2, 3]),
    controlEdges: new Uint32Array(0),
  });

  it("gives each vertex's distance to the other surface: its own distances worked out by hand", () => {
    const h = hausdorffDistance(square(0), square(0, 2), true);
    // The unit square lies in the 2 x 2 one; the larger one's corners (0,0), (2,0), (2,2), (0,2)
    // are 0, 1, sqrt 2 and 1 from it, and sqrt 2 is the Hausdorff distance.
    expect(Array.from(h.aToB ?? [])).toEqual([0, 0, 0, 0]);
    const expected = [0, 1, Math.SQRT2, 1];
    for (const [v, d] of (h.bToA ?? []).entries()) expect(d).toBeCloseTo(expected[v], 15);
    expect(h.bToA).toHaveLength(4);
    expect(Math.abs(h.distance - Math.SQRT2)).toBeLessThanOrEqual(h.errorBound);
    expect(hausdorffDistance(square(0), square(0.1)).aToB).toBeUndefined();
  });

  it('keeps every vertex within the distance for Catmull-Clark against Loop on the cube', () => {
    const cube = loadFixture('cube.off');
    const cc = subdivide(cube, { scheme: 'catmull-clark', levels: 2 });
    const loop = subdivide(cube, { scheme: 'loop', levels: 2, triangulate: true });
    const h = hausdorffDistance(cc, loop, true);
    expect(h.aToB).toHaveLength(cc.positions.length / 3);
    expect(h.bToA).toHaveLength(loop.positions.length / 3);
    const farthest = Math.max(...(h.aToB ?? []), ...(h.bToA ?? []));
    expect(farthest).toBeLessThanOrEqual(h.distance + h.errorBound);
    expect(farthest).toBeGreaterThan(0.5 * h.distance);
  });
});
