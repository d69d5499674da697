/**
 * CGAL's geometry around a mesh in the WebAssembly core (no GMP: Boost's
 * exact numbers, CGAL_ALWAYS_ROUND_TO_NEAREST): the closed forms the native
 * tests check, the native core's own figures to the last digit for counts
 * and 1e-12 for lengths (tests/fixtures/inspect-reference.txt), and
 * `subdiv inspect`.
 */
import { spawnSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { beforeAll, describe, expect, it } from 'vitest';
import { initNode } from '../../web/core/init-node';
import type { SchemeName } from '../../web/core/mesh';
import { inspectMesh, subdivide } from '../../web/core/subdiv-core';
import { FIXTURES_DIR, loadFixture } from './test-helpers';

const ROOT = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
const ALL = { selfIntersections: true, sphere: true, hull: true, width: true };

beforeAll(async () => {
  await initNode();
});

describe('inspectMesh', () => {
  it('counts the crossing face pairs: 12 for the stella octangula, 1 for two crossing squares, none on the cube', () => {
    const stella = inspectMesh(loadFixture('stella-octangula.off'), ALL).selfIntersections;
    expect(stella?.pairs).toBe(12);
    expect(Array.from(stella?.faces ?? [])).toEqual([0, 1, 2, 3, 4, 5, 6, 7]);
    const squares = inspectMesh(loadFixture('crossing-squares.off'), { selfIntersections: true });
    expect(Array.from(squares.selfIntersections?.firstPairs ?? [])).toEqual([0, 1]);
    expect(inspectMesh(loadFixture('cube.off'), ALL).selfIntersections?.pairs).toBe(0);
    expect(
      inspectMesh(loadFixture('stella-octangula.off'), { selfIntersections: true, maxPairs: 3 }).selfIntersections
        ?.firstPairs,
    ).toHaveLength(6);
  });

  it('gives the cube and the regular simplex their closed forms', () => {
    const cube = inspectMesh(loadFixture('cube.off'), ALL);
    expect(cube.sphere?.radius).toBeCloseTo(Math.sqrt(3), 12);
    expect(cube.hull).toMatchObject({ vertices: 8, edges: 18, faces: 12 });
    expect(cube.hull?.area).toBeCloseTo(24, 12);
    expect(cube.hull?.volume).toBeCloseTo(8, 12);
    expect(cube.width?.width).toBeCloseTo(2, 12);
    expect(Math.abs((cube.width?.offsets[0] ?? 0) - (cube.width?.offsets[1] ?? 0))).toBeCloseTo(2, 12);
    expect(cube.measures).toMatchObject({ closed: true, bboxMin: [-1, -1, -1], bboxMax: [1, 1, 1] });
    expect(cube.measures.volume).toBeCloseTo(8, 12);
    const simplex = inspectMesh(loadFixture('tetrahedron.off'), ALL);
    expect(simplex.sphere?.radius).toBeCloseTo(Math.sqrt(3), 12);
    expect(simplex.width?.width).toBeCloseTo(2, 12);
    expect(simplex.hull?.volume).toBeCloseTo(8 / 3, 12);
    expect(simplex.measures.area).toBeCloseTo(8 * Math.sqrt(3), 12);
    // Only what was asked.
    expect(Object.keys(inspectMesh(loadFixture('cube.off')))).toEqual(['measures']);
  });

  it('gives the native core’s figures (tests/fixtures/inspect-reference.txt)', () => {
    const lines = readFileSync(join(FIXTURES_DIR, 'inspect-reference.txt'), 'utf8')
      .split('\n')
      .filter((line) => line.trim() !== '' && !line.startsWith('#'));
    expect(lines).toHaveLength(6);
    for (const line of lines) {
      const w = line.trim().split(/\s+/);
      const [name, scheme, levels] = [w[0], w[1] as SchemeName, Number(w[2])];
      const n = (k: number) => Number(w[k]);
      const mesh = subdivide(loadFixture(name), { scheme, levels, triangulate: true });
      const i = inspectMesh(mesh, ALL);
      const where = `${name} ${scheme} ${levels}`;
      expect(i.selfIntersections?.pairs, where).toBe(n(4));
      expect([i.hull?.vertices, i.hull?.edges, i.hull?.faces], where).toEqual([n(15), n(16), n(17)]);
      const close = (got: number | undefined, want: number) =>
        expect(Math.abs((got ?? Number.NaN) - want), where).toBeLessThanOrEqual(1e-12);
      close(i.measures.area, n(6));
      close(i.measures.volume, n(8));
      close(i.sphere?.radius, n(10));
      for (let k = 0; k < 3; ++k) close(i.sphere?.center[k], n(11 + k));
      close(i.hull?.area, n(18));
      close(i.hull?.volume, n(19));
      close(i.width?.width, n(21));
    }
  });
});

describe('subdiv inspect', () => {
  const subdiv = (args: string[]) =>
    spawnSync(process.execPath, [join(ROOT, 'bin', 'subdiv.mjs'), ...args], { cwd: ROOT, encoding: 'utf8' });

  it('prints every computation by default, and only those chosen', () => {
    const r = subdiv(['inspect', join(FIXTURES_DIR, 'stella-octangula.off')]);
    expect(r.stderr).toBe('');
    expect(r.status).toBe(0);
    const out = JSON.parse(r.stdout);
    expect(Object.keys(out)).toEqual(['vertices', 'faces', 'measures', 'selfIntersections', 'sphere', 'hull', 'width']);
    expect(out.selfIntersections.pairs).toBe(12);
    expect(out.selfIntersections.firstPairs[0]).toEqual([0, 5]);
    expect(out.sphere.radius).toBeCloseTo(Math.sqrt(3), 12);
    const some = JSON.parse(subdiv(['inspect', join(FIXTURES_DIR, 'cube.off'), '--hull', '--width']).stdout);
    expect(Object.keys(some)).toEqual(['vertices', 'faces', 'measures', 'hull', 'width']);
    expect(some.width.width).toBeCloseTo(2, 12);
  });

  it('inspects a level and says how much the scheme shrank the model', () => {
    const out = JSON.parse(subdiv(['inspect', join(FIXTURES_DIR, 'cube.off'), '--levels', '2', '--sphere']).stdout);
    expect(out).toMatchObject({ scheme: 'catmull-clark', levels: 2, vertices: 98, faces: 96 });
    expect(out.control.volume).toBeCloseTo(8, 12);
    expect(out.change.volume).toBeCloseTo(out.measures.volume / 8, 12);
    expect(out.change.diagonal).toBeCloseTo(out.measures.diagonal / (2 * Math.sqrt(3)), 12);
    // Catmull-Clark pulls the cube's corners in: the level fits in a smaller box.
    expect(out.change.diagonal).toBeLessThan(1);
  });

  it('names the file, the line and the problem of a mesh it cannot inspect', () => {
    const bad = subdiv(['inspect', join(FIXTURES_DIR, 'invalid', 'index-out-of-range.off')]);
    expect(bad.status).toBe(1);
    expect(bad.stdout).toBe('');
    expect(bad.stderr).toMatch(
      /^error: .*index-out-of-range\.off: line 8: face index 12 is out of range \(4 vertices\)\n$/,
    );
    const quads = subdiv(['inspect', join(FIXTURES_DIR, 'cube.off'), '--scheme', 'loop', '--levels', '1']);
    expect(quads.status).toBe(1);
    expect(quads.stderr).toMatch(/^error: .*cube\.off: loop needs a triangle mesh: 6 of 6 faces are not triangles/);
  });

  it('refuses options of other commands', () => {
    const r = subdiv(['inspect', join(FIXTURES_DIR, 'cube.off'), '-o', 'x.off']);
    expect(r.status).toBe(2);
    expect(r.stderr).toMatch(/^subdiv: subdiv inspect takes no --output\n/);
    const other = subdiv([join(FIXTURES_DIR, 'cube.off'), '--hull']);
    expect(other.status).toBe(2);
    expect(other.stderr).toMatch(/^subdiv: --hull belongs to another command\n/);
  });
});
