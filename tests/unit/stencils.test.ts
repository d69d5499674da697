/**
 * Stencils through the WASM core (stepStencils) and `subdiv stencil`: every
 * vertex of levels 1-2 of every scheme, custom rule sets on the four hosts
 * included, on closed and open meshes, is the weighted sum of its parents
 * (to 1e-12) with weights summing to 1; the known masks come out exactly.
 */
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { beforeAll, describe, expect, it } from 'vitest';
import { initNode } from '../../web/core/init-node';
import type { Mesh, SchemeName, SubdivideOptions } from '../../web/core/mesh';
import { parseRuleSetText, type RuleSet } from '../../web/core/rule-set';
import { fraction, vertexStencil } from '../../web/core/stencils';
import { parseMesh, stepStencils, subdivide } from '../../web/core/subdiv-core';
import { SubdivError } from '../../web/core/subdiv-error';
import { stencilKindText, stencilSum } from '../../web/teach/stencil-inspector';
import { FIXTURES_DIR, loadFixture } from './test-helpers';

const ROOT = join(dirname(fileURLToPath(import.meta.url)), '..', '..');

beforeAll(async () => {
  await initNode();
});

function preset(name: string): RuleSet {
  return parseRuleSetText(readFileSync(join(ROOT, 'public', 'rules', `${name}.json`), 'utf8'));
}

/** Level k of `mesh` as subdivide makes it (k = 0: the mesh). */
function levelOf(mesh: Mesh, options: SubdivideOptions, k: number): Mesh {
  return k === 0 ? mesh : subdivide(mesh, { ...options, levels: k });
}

function expectStencilsGivePoints(name: string, options: Omit<SubdivideOptions, 'levels'>) {
  const mesh = loadFixture(name);
  for (const k of [1, 2]) {
    const table = stepStencils(mesh, { ...options, levels: k });
    const parent = levelOf(mesh, { ...options, levels: k }, k - 1);
    const child = levelOf(mesh, { ...options, levels: k }, k);
    expect(table.parentVertices).toBe(parent.positions.length / 3);
    expect(table.kinds.length).toBe(child.positions.length / 3);
    let worst = 0;
    for (let v = 0; v < table.kinds.length; ++v) {
      const s = vertexStencil(table, v);
      const sum = s.parents.reduce((t, p) => t + p.weight, 0);
      worst = Math.max(worst, Math.abs(sum - 1));
      for (let i = 0; i < 3; ++i) {
        const p = s.parents.reduce((t, q) => t + q.weight * parent.positions[3 * q.vertex + i], 0);
        const want = child.positions[3 * v + i];
        worst = Math.max(worst, Math.abs(p - want) / Math.max(1, Math.abs(want)));
      }
    }
    expect(worst, `${name} ${options.scheme} level ${k}`).toBeLessThan(1e-12);
  }
}

describe('stepStencils', () => {
  const quads = ['cube.off', 'grid-open.off', 'mixed-open.off'];
  const triangles = ['octahedron.off', 'disk-tri.off', 'torus-tri.off'];
  for (const scheme of ['catmull-clark', 'doo-sabin', 'quad-triangle', 'linear'] as SchemeName[]) {
    it(`${scheme}: every vertex of levels 1-2 from its parents`, () => {
      for (const f of quads) expectStencilsGivePoints(f, { scheme });
    });
  }
  for (const scheme of ['loop', 'sqrt3', 'linear-tri'] as SchemeName[]) {
    it(`${scheme}: every vertex of levels 1-2 from its parents`, () => {
      for (const f of triangles) expectStencilsGivePoints(f, { scheme });
    });
  }
  it('custom rule sets on the four hosts, and the improved-Loop preset', () => {
    for (const f of quads) {
      expectStencilsGivePoints(f, { scheme: 'custom', rules: preset('catmull-clark') });
      expectStencilsGivePoints(f, { scheme: 'custom', rules: preset('doo-sabin') });
    }
    for (const f of triangles) {
      for (const name of ['loop', 'sqrt3', 'improved-loop'])
        expectStencilsGivePoints(f, { scheme: 'custom', rules: preset(name) });
    }
  });

  it('the known masks exactly: Catmull-Clark 9/16, 3/32, 1/64; Loop 3/8, 1/8 and beta(6) = 1/16', () => {
    const cc = vertexStencil(stepStencils(loadFixture('grid-open.off'), { scheme: 'catmull-clark', levels: 1 }), 5);
    expect(cc.kind).toBe('vertex point');
    expect(cc.size).toBe(4);
    expect(cc.parents.map((p) => [p.vertex, fraction(p.weight)])).toEqual([
      [0, '1/64'],
      [1, '3/32'],
      [2, '1/64'],
      [4, '3/32'],
      [5, '9/16'],
      [6, '3/32'],
      [8, '1/64'],
      [9, '3/32'],
      [10, '1/64'],
    ]);
    const loop = stepStencils(loadFixture('torus-tri.off'), { scheme: 'loop', levels: 1 });
    const vertex = vertexStencil(loop, 0);
    expect(vertex.size).toBe(6);
    expect(vertex.parents.map((p) => fraction(p.weight))).toEqual(['5/8', ...Array(6).fill('1/16')]);
    const edge = vertexStencil(loop, 48);
    expect(edge.kind).toBe('edge point');
    const ends: number[] = edge.edge ?? [];
    for (const p of edge.parents) expect(fraction(p.weight)).toBe(ends.includes(p.vertex) ? '3/8' : '1/8');
    expect(edge.formula).toContain('3/8');
  });

  it('refuses a call without a step, as a SubdivError', () => {
    expect(() => stepStencils(loadFixture('cube.off'), { scheme: 'catmull-clark', levels: 0 })).toThrow(SubdivError);
  });
});

describe('fraction', () => {
  it('writes rational weights with small denominators exactly, others not at all', () => {
    expect(fraction(0.375)).toBe('3/8');
    expect(fraction(1 / 3)).toBe('1/3');
    expect(fraction(5 / 12)).toBe('5/12');
    expect(fraction(1)).toBe('1');
    expect(fraction(0.1)).toBe('1/10');
    expect(fraction(-0.0625)).toBe('-1/16');
    expect(fraction(Math.PI)).toBeNull();
    // Loop's beta(5) is irrational.
    const beta5 = (5 / 8 - (3 / 8 + Math.cos((2 * Math.PI) / 5) / 4) ** 2) / 5;
    expect(fraction(beta5)).toBeNull();
    expect(fraction(Number.NaN)).toBeNull();
  });
});

describe('stencils in words (the app panel and the <subdiv-viewer> caption)', () => {
  it('group equal weights, largest first; name the vertex, edge or face and its valence', () => {
    const cc = vertexStencil(stepStencils(loadFixture('grid-open.off'), { scheme: 'catmull-clark', levels: 1 }), 5);
    expect(stencilSum(cc)).toBe('9/16·v5 + 3/32·(v1 + v4 + v6 + v9) + 1/64·(v0 + v2 + v8 + v10)');
    expect(stencilKindText(cc)).toBe('vertex point of vertex 5, valence 4');
    const edge = vertexStencil(stepStencils(loadFixture('torus-tri.off'), { scheme: 'loop', levels: 1 }), 48);
    const [a, b] = edge.edge ?? [-1, -1];
    expect(stencilKindText(edge)).toBe(`edge point of edge ${a}–${b}`);
    expect(stencilSum(edge)).toMatch(
      new RegExp(`^3/8·\\(v${Math.min(a, b)} \\+ v${Math.max(a, b)}\\) \\+ 1/8·\\(v\\d+ \\+ v\\d+\\)$`),
    );
  });

  it('write a negative weight as a difference, and decimals where no fraction is exact', () => {
    const stencil = {
      vertex: 0,
      kind: 'edge point',
      element: null,
      size: 0,
      edge: [0, 1] as [number, number],
      formula: '',
      parents: [
        { vertex: 0, weight: 0.5 },
        { vertex: 1, weight: 0.5 },
        { vertex: 2, weight: -1 / 16 },
        { vertex: 3, weight: Math.PI / 100 },
      ],
    };
    expect(stencilSum(stencil)).toBe('1/2·(v0 + v1) + 0.0314·v3 − 1/16·v2');
  });
});

describe('subdiv stencil', () => {
  const BIN = join(ROOT, 'bin', 'subdiv.mjs');
  const subdiv = (args: string[]) => spawnSync(process.execPath, [BIN, ...args], { cwd: ROOT, encoding: 'utf8' });

  it('prints the stencil of a vertex numbered as --levels K writes it', () => {
    const input = join(FIXTURES_DIR, 'octahedron.off');
    const r = subdiv(['stencil', input, '--scheme', 'loop', '--level', '2', '--vertex', '20']);
    expect(r.stderr).toBe('');
    expect(r.status).toBe(0);
    const out = JSON.parse(r.stdout);
    expect(out).toMatchObject({ scheme: 'loop', level: 2, vertex: 20, kind: 'edge point' });
    expect(out.parents.map((p: { fraction: string }) => p.fraction).sort()).toEqual(['1/8', '1/8', '3/8', '3/8']);
    expect(out.sum).toBeCloseTo(1, 14);
    // The position is vertex 20 of what `subdiv --levels 2 -o` writes.
    const work = mkdtempSync(join(tmpdir(), 'subdiv-stencil-'));
    const file = join(work, 'level2.off');
    expect(subdiv([input, '--scheme', 'loop', '--levels', '2', '-o', file]).status).toBe(0);
    const written = parseMesh(readFileSync(file, 'utf8'), 'off');
    expect(out.position).toEqual(Array.from(written.positions.subarray(60, 63)));
    // The parents are level 1's vertices as --levels 1 writes them.
    const level1 = subdivide(loadFixture('octahedron.off'), { scheme: 'loop', levels: 1 });
    const sum = [0, 1, 2].map((i) =>
      out.parents.reduce(
        (t: number, p: { vertex: number; weight: number }) => t + p.weight * level1.positions[3 * p.vertex + i],
        0,
      ),
    );
    for (let i = 0; i < 3; ++i) expect(sum[i]).toBeCloseTo(out.position[i], 12);
  });

  it('says which vertices exist, and what a stencil needs', () => {
    const input = join(FIXTURES_DIR, 'cube.off');
    const far = subdiv(['stencil', input, '--level', '1', '--vertex', '26']);
    expect(far.status).toBe(1);
    expect(far.stderr).toBe(`error: ${input}: level 1 has 26 vertices (0 to 25), so no vertex 26\n`);
    const noLevel = subdiv(['stencil', input, '--vertex', '3']);
    expect(noLevel.status).toBe(2);
    expect(noLevel.stderr).toMatch(/^subdiv: subdiv stencil needs --level\n/);
    const zero = subdiv(['stencil', input, '--level', '0', '--vertex', '3']);
    expect(zero.status).toBe(2);
    expect(zero.stderr).toMatch(/^subdiv: --level must be an integer 1 or more, not "0"\n/);
    const output = subdiv(['stencil', input, '--level', '1', '--vertex', '3', '-o', 'x.off']);
    expect(output.status).toBe(2);
    expect(output.stderr).toMatch(/^subdiv: subdiv stencil takes no --output\n/);
  });
});
