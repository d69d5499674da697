/**
 * Issue 4 in TS: the safe expression parser, rule files (parse, compile,
 * presets through the WASM core against the built-in schemes), the new
 * schemes and options through the API, and the CLI's --rule, --fixed-boundary
 * and controlEdges.
 */
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { beforeAll, describe, expect, it } from 'vitest';
import { evaluateExpression, parseExpression } from '../../web/core/expression';
import { initNode } from '../../web/core/init-node';
import type { Mesh, SchemeName, SubdivideOptions } from '../../web/core/mesh';
import {
  compileRuleSet,
  parseRuleSet,
  parseRuleSetText,
  RULE_PRESETS,
  type RuleSet,
  ruleSetToText,
} from '../../web/core/rule-set';
import { checkRules, meshFacts, predictSize, schemeNames, subdivide } from '../../web/core/subdiv-core';
import { SubdivError } from '../../web/core/subdiv-error';
import { FIXTURES_DIR, loadFixture, rulePreset as preset } from './test-helpers';

const ROOT = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
const RULES_DIR = join(ROOT, 'public', 'rules');

/** Largest coordinate difference; same counts and faces required. */
function expectSameMesh(a: Mesh, b: Mesh, tol: number): void {
  expect(a.faceSizes).toEqual(b.faceSizes);
  expect(a.faceIndices).toEqual(b.faceIndices);
  expect(a.positions.length).toBe(b.positions.length);
  let worst = 0;
  for (let i = 0; i < a.positions.length; i++) worst = Math.max(worst, Math.abs(a.positions[i] - b.positions[i]));
  expect(worst).toBeLessThanOrEqual(tol);
}

function expectRefused(f: () => unknown, message: string | RegExp): void {
  let caught: unknown;
  try {
    f();
  } catch (error) {
    caught = error;
  }
  expect(caught).toBeInstanceOf(SubdivError);
  expect((caught as SubdivError).code).toBe('invalid_argument');
  if (typeof message === 'string') expect((caught as SubdivError).message).toBe(message);
  else expect((caught as SubdivError).message).toMatch(message);
}

beforeAll(async () => {
  await initNode();
});

describe('expression parser', () => {
  it('evaluates numbers, n and k, + - * / ^, parentheses, cos, sin, sqrt and pi', () => {
    expect(evaluateExpression('1 + 2 * 3')).toBe(7);
    expect(evaluateExpression('(1 + 2) * 3')).toBe(9);
    expect(evaluateExpression('2 ^ 3 ^ 2')).toBe(512); // right-associative
    expect(evaluateExpression('-2 ^ 2')).toBe(-4); // ^ binds tighter than unary minus
    expect(evaluateExpression('10 / 4 - 1.5e1 + .5')).toBe(-12);
    expect(evaluateExpression('3/(8*n)', { n: 5 })).toBe(3 / 40);
    expect(evaluateExpression('(5/k + 1)/4', { k: 4 })).toBe(9 / 16);
    expect(evaluateExpression('cos(pi) + sin(pi/2) + sqrt(16)')).toBe(4);
    const loopBeta = parseExpression('(5/8 - (3 + 2*cos(2*pi/n))^2/64)/n', ['n']);
    for (const n of [3, 4, 5, 7, 12]) {
      const t = 3 + 2 * Math.cos((2 * Math.PI) / n);
      expect(loopBeta.evaluate({ n })).toBeCloseTo((5 / 8 - (t * t) / 64) / n, 15);
    }
    expect([...loopBeta.variables]).toEqual(['n']);
  });

  it('refuses everything else, naming what and where', () => {
    expectRefused(() => parseExpression('alert(1)', ['n']), /unknown name "alert" at column 1/);
    expectRefused(() => parseExpression('n; 1', ['n']), 'expression "n; 1": unexpected character ";" at column 2');
    expectRefused(() => parseExpression('Math.cos(n)', ['n']), /unexpected character "\." at column 5/);
    expectRefused(() => parseExpression('Math(n)', ['n']), /unknown name "Math" at column 1/);
    expectRefused(() => parseExpression('n.constructor', ['n']), /unexpected character "\." at column 2/);
    expectRefused(() => parseExpression('x * 2', ['n']), /unknown name "x" at column 1 \(allowed: numbers, pi, n,/);
    expectRefused(() => parseExpression('k', ['n']), /unknown name "k"/);
    expectRefused(() => parseExpression('(1 + 2', ['n']), 'expression "(1 + 2": expected ")" but found at the end');
    expectRefused(() => parseExpression('1 +', ['n']), /expected a number, a name or "\(" but found at the end/);
    expectRefused(() => parseExpression('2 3', ['n']), /unexpected "3" at column 3/);
    expectRefused(() => parseExpression('', ['n']), 'expression "": empty');
    expectRefused(() => parseExpression('`1`', ['n']), /unexpected character "`"/);
    expectRefused(() => parseExpression('cos 1', ['n']), /expected "\(" but found "1"/);
    expectRefused(() => parseExpression('1 == 1', ['n']), /unexpected character "="/);
    expectRefused(() => parseExpression('[1]', ['n']), /unexpected character "\["/);
    expectRefused(() => parseExpression('n'.repeat(1001), ['n']), /longer than 1000 characters/);
  });
});

describe('rule files', () => {
  it('every preset loads, names its host, and round-trips through its text', () => {
    const hosts: Record<string, string> = {
      'catmull-clark': 'pqq',
      loop: 'ptq',
      'doo-sabin': 'dqq',
      sqrt3: 'sqrt3',
      'improved-loop': 'ptq',
      linear: 'pqq',
    };
    expect([...RULE_PRESETS].sort()).toEqual(Object.keys(hosts).sort());
    for (const name of RULE_PRESETS) {
      const rules = preset(name);
      expect(rules.host).toBe(hosts[name]);
      expect(parseRuleSetText(ruleSetToText(rules))).toEqual(rules);
    }
  });

  it('compiles formulas into tables for valences and degrees 3..max', () => {
    const loop = compileRuleSet(preset('loop'), { maxValence: 8 });
    expect(loop.firstValence).toBe(3);
    expect(loop.vertex).toHaveLength(3 * 6);
    // valence 6 comes from the per-valence entry, exactly 10/16 and 1/16
    expect(loop.vertex.slice(9, 12)).toEqual([10 / 16, 1 / 16, 0]);
    expect(loop.edge).toEqual([3 / 8, 1 / 8]);
    const ds = compileRuleSet(preset('doo-sabin'), { maxDegree: 5 });
    expect(ds.corner).toHaveLength(3 + 4 + 5);
    expect(ds.corner.slice(3, 7).map((w) => Math.round(w * 16 * 1e12) / 1e12)).toEqual([9, 3, 1, 3]);
    // Default tables: 3..64.
    expect(compileRuleSet(preset('catmull-clark')).vertex).toHaveLength(3 * 62);
  });

  it('refuses malformed rule files with the path of the problem', () => {
    expectRefused(() => parseRuleSetText('{ "host": '), /^rule set: file: not valid JSON/);
    expectRefused(
      () => parseRuleSet({ host: 'pqt' }),
      'rule set: host: expected one of pqq, ptq, dqq, sqrt3, got "pqt"',
    );
    expectRefused(
      () => parseRuleSet({ host: 'ptq', vertex: { self: 1, neighbour: 0 } }),
      'rule set: edge: the ptq host needs a edge rule',
    );
    expectRefused(
      () => parseRuleSet({ host: 'dqq', corner: { self: 1, other: 0 }, edge: { end: 0.5, wing: 0 } }),
      'rule set: edge: the dqq host has no edge rule',
    );
    expectRefused(
      () => parseRuleSet({ host: 'ptq', vertex: { self: 1, neighbour: 'eval(n)' }, edge: { end: 0.5, wing: 0 } }),
      /^rule set: vertex.neighbour: expression "eval\(n\)": unknown name "eval"/,
    );
    expectRefused(
      () => parseRuleSet({ host: 'ptq', vertex: { self: 1, neighbour: 0, face: 0 }, edge: { end: 0.5, wing: 0 } }),
      'rule set: vertex: unknown key "face" (expected self, neighbour)',
    );
    expectRefused(
      () => parseRuleSet({ host: 'pqq', vertex: { self: { six: 1 }, neighbour: 0 }, edge: { end: 0.5, wing: 0 } }),
      'rule set: vertex.self: key "six" is neither a valence (a whole number) nor "default"',
    );
    expectRefused(
      () => parseRuleSet({ host: 'pqq', vertex: { self: 1, neighbour: 0 }, edge: { end: 'n/2', wing: 0 } }),
      /^rule set: edge.end: expression "n\/2": unknown name "n"/,
    );
    expectRefused(
      () =>
        parseRuleSet({
          host: 'pqq',
          vertex: { self: 1, neighbour: 0 },
          edge: { end: 0.5, wing: 0 },
          border: { vertex: [1, 0] },
        }),
      'rule set: border.vertex: expected an array of 3 weights',
    );
    expectRefused(
      () => parseRuleSet({ host: 'pqq', vertex: { self: 1, neighbour: 0 }, edge: { end: 0.5, wing: 0 }, script: 'x' }),
      /^rule set: file: unknown key "script"/,
    );
  });
});

describe('new schemes through the WASM core', () => {
  it('lists quad-triangle, linear, linear-tri and custom', () => {
    expect(schemeNames()).toEqual(expect.arrayContaining(['quad-triangle', 'linear', 'linear-tri', 'custom']));
  });

  it('quad-triangle equals catmull-clark on the quad torus and loop on the triangle torus', () => {
    const quad = loadFixture('torus-quad.off');
    const tri = loadFixture('torus-tri.off');
    expectSameMesh(
      subdivide(quad, { scheme: 'quad-triangle', levels: 2 }),
      subdivide(quad, { scheme: 'catmull-clark', levels: 2 }),
      1e-12,
    );
    expectSameMesh(
      subdivide(tri, { scheme: 'quad-triangle', levels: 2 }),
      subdivide(tri, { scheme: 'loop', levels: 2 }),
      1e-12,
    );
  });

  it('quad-triangle on the rhombicuboctahedron: 32 triangles and 72 quads, counts predicted', () => {
    const mesh = loadFixture('rhombicuboctahedron.off');
    const out = subdivide(mesh, { scheme: 'quad-triangle', levels: 1 });
    const facts = meshFacts(out);
    expect(facts).toMatchObject({ triangles: 32, quads: 72, otherFaces: 0, vertices: 90, genus: 0, closed: true });
    expect(facts.controlEdges).toBe(96);
    const p = predictSize(mesh, { scheme: 'quad-triangle', levels: 1 });
    expect([p.vertices, p.edges, p.faces]).toEqual([facts.vertices, facts.edges, facts.faces]);
  });

  it('smoothBoundary: false keeps the border polygon of an open grid', () => {
    const grid = loadFixture('grid-open.off'); // [0, 3]^2
    const fixed = subdivide(grid, { scheme: 'quad-triangle', levels: 1, smoothBoundary: false });
    const smooth = subdivide(grid, { scheme: 'quad-triangle', levels: 1 });
    expect([fixed.positions[0], fixed.positions[1]]).toEqual([0, 0]);
    expect(smooth.positions[0]).toBeGreaterThan(0);
  });

  it('linear and linear-tri keep the vertices and put new ones at midpoints', () => {
    const mixed = loadFixture('mixed-open.off');
    const out = subdivide(mixed, { scheme: 'linear', levels: 1 });
    expect(out.positions.subarray(0, mixed.positions.length)).toEqual(mixed.positions);
    expect(meshFacts(out).quads).toBe(meshFacts(out).faces);
    const disk = loadFixture('disk-tri.off');
    const tri = subdivide(disk, { scheme: 'linear-tri', levels: 1 });
    expect(tri.positions.subarray(0, disk.positions.length)).toEqual(disk.positions);
    expect(meshFacts(tri).triangles).toBe(24);
  });

  it('each preset equals its built-in scheme, closed and open, to 1e-12', () => {
    const cases: [string, SchemeName, string][] = [
      ['catmull-clark', 'catmull-clark', 'cube.off'],
      ['catmull-clark', 'catmull-clark', 'mixed-open.off'],
      ['loop', 'loop', 'icosahedron.off'],
      ['loop', 'loop', 'disk-tri.off'],
      ['doo-sabin', 'doo-sabin', 'cube.off'],
      ['doo-sabin', 'doo-sabin', 'grid-open.off'],
      ['sqrt3', 'sqrt3', 'icosahedron.off'],
      ['sqrt3', 'sqrt3', 'disk-tri.off'],
      ['linear', 'linear', 'mixed-open.off'],
    ];
    for (const [name, scheme, fixture] of cases) {
      const mesh = loadFixture(fixture);
      const custom = subdivide(mesh, { scheme: 'custom', levels: 3, rules: preset(name) });
      const builtIn = subdivide(mesh, { scheme, levels: 3 });
      expectSameMesh(custom, builtIn, 1e-12);
    }
  });

  it('improved-loop follows Warren at valence 4', () => {
    const octa = loadFixture('octahedron.off');
    const out = subdivide(octa, { scheme: 'custom', levels: 1, rules: preset('improved-loop') });
    // Vertex 0 and its four neighbours: 5/8 v + 3/32 sum.
    const p = (m: Mesh, i: number) => [m.positions[3 * i], m.positions[3 * i + 1], m.positions[3 * i + 2]];
    const ring = new Set<number>();
    let o = 0;
    for (const k of octa.faceSizes) {
      const f = Array.from(octa.faceIndices.subarray(o, o + k));
      if (f.includes(0)) for (const v of f) if (v !== 0) ring.add(v);
      o += k;
    }
    expect(ring.size).toBe(4);
    const expected = p(octa, 0).map(
      (x, c) => (5 / 8) * x + (3 / 32) * [...ring].reduce((s, v) => s + p(octa, v)[c], 0),
    );
    for (const [c, x] of p(out, 0).entries()) expect(x).toBeCloseTo(expected[c], 14);
  });

  it('the core refuses weights that are not finite or do not sum to 1, naming rule and valence', () => {
    const cube = loadFixture('cube.off');
    const bad: RuleSet = {
      ...preset('catmull-clark'),
      vertex: { self: '(n - 2)/n + 0.1', neighbour: '1/n^2', face: '1/n^2' },
    };
    expectRefused(
      () => subdivide(cube, { scheme: 'custom', levels: 1, rules: bad }),
      'custom rules: the vertex rule at valence 3 sums to 1.1, not 1',
    );
    const nan: RuleSet = {
      ...preset('catmull-clark'),
      vertex: { self: { 5: 'sqrt(-1)', default: '(n - 2)/n' }, neighbour: '1/n^2', face: '1/n^2' },
    };
    expectRefused(
      () => subdivide(cube, { scheme: 'custom', levels: 1, rules: nan }),
      'custom rules: the vertex rule at valence 5 has a weight that is not finite (nan)',
    );
    const ds: RuleSet = { host: 'dqq', corner: { self: '1/k', other: '1/k + 0.01' } };
    expectRefused(
      () => subdivide(cube, { scheme: 'custom', levels: 1, rules: ds }),
      'custom rules: the corner rule at degree 3 sums to 1.02, not 1',
    );
    expectRefused(
      () => subdivide(cube, { scheme: 'custom', levels: 1 }),
      'scheme custom needs a rule set (option rules)',
    );
    // checkRules: the same verdicts without a mesh (the rules panel's feedback).
    expectRefused(() => checkRules(bad), 'custom rules: the vertex rule at valence 3 sums to 1.1, not 1');
    expectRefused(
      () => checkRules(nan),
      'custom rules: the vertex rule at valence 5 has a weight that is not finite (nan)',
    );
    expectRefused(() => checkRules(ds), 'custom rules: the corner rule at degree 3 sums to 1.02, not 1');
    const warren: RuleSet = { ...preset('loop'), vertex: { self: '5/8', neighbour: '3/(8*n)' } };
    for (const rules of [...RULE_PRESETS.map(preset), warren]) expect(() => checkRules(rules)).not.toThrow();
    expectRefused(
      () => checkRules({ ...preset('loop'), border: { vertex: ['1/8', '3/4', 'sqrt(-1)'] } }),
      'custom rules: the border vertex rule has a weight that is not finite (nan)',
    );
    // The module keeps working.
    expect(meshFacts(subdivide(cube, { scheme: 'custom', levels: 1, rules: preset('linear') })).faces).toBe(24);
  });

  it('control edges: a cube at level 3 of catmull-clark has 96 marked edges; dual schemes none', () => {
    const cube = loadFixture('cube.off');
    const out = subdivide(cube, { scheme: 'catmull-clark', levels: 3 });
    expect(out.controlEdges.length).toBe(2 * 96);
    expect(meshFacts(out).controlEdges).toBe(96);
    // Stepping level by level, handing the marks on, keeps 12 * 2^k of them.
    let step = cube;
    for (let level = 0; level < 3; level++) {
      const options: SubdivideOptions = { scheme: 'catmull-clark', levels: 1, startLevel: level };
      step = subdivide(step, options);
      expect(step.controlEdges.length).toBe(2 * 12 * 2 ** (level + 1));
    }
    expect(subdivide(cube, { scheme: 'doo-sabin', levels: 1 }).controlEdges.length).toBe(0);
  });
});

describe('subdiv CLI with rules', () => {
  const BIN = join(ROOT, 'bin', 'subdiv.mjs');
  const run = (args: string[]) => {
    const r = spawnSync(process.execPath, [BIN, ...args], { cwd: ROOT, encoding: 'utf8' });
    return { status: r.status, stdout: r.stdout, stderr: r.stderr };
  };
  const fixture = (name: string) => join(FIXTURES_DIR, name);

  it('--scheme custom --rule FILE equals the built-in scheme, with controlEdges in --stats', () => {
    const custom = run([
      fixture('cube.off'),
      '--scheme',
      'custom',
      '--rule',
      join(RULES_DIR, 'catmull-clark.json'),
      '--levels',
      '2',
      '--stats',
    ]);
    expect(custom.stderr).toBe('');
    expect(custom.status).toBe(0);
    const builtIn = run([fixture('cube.off'), '--levels', '2', '--stats']);
    const a = JSON.parse(custom.stdout);
    const b = JSON.parse(builtIn.stdout);
    delete a.ms;
    delete b.ms;
    expect(a).toEqual(b);
    expect(a.controlEdges).toBe(48);
    // --rule alone implies custom; the written meshes are identical but for the comment naming the scheme.
    const dir = mkdtempSync(join(tmpdir(), 'subdiv-rules-'));
    run([fixture('icosahedron.off'), '--rule', join(RULES_DIR, 'loop.json'), '-o', join(dir, 'a.off')]);
    run([fixture('icosahedron.off'), '--scheme', 'loop', '-o', join(dir, 'b.off')]);
    const a2 = readFileSync(join(dir, 'a.off'), 'utf8').split('\n');
    const b2 = readFileSync(join(dir, 'b.off'), 'utf8').split('\n');
    expect(a2[1]).toBe('# SubdivLab: icosahedron.off, Custom rules, level 1');
    expect(b2[1]).toBe('# SubdivLab: icosahedron.off, Loop, level 1');
    expect([a2[0], ...a2.slice(2)]).toEqual([b2[0], ...b2.slice(2)]);
  });

  it('quad-triangle, --fixed-boundary and controlEdges on the CLI', () => {
    const r = run([fixture('rhombicuboctahedron.off'), '--scheme', 'quad-triangle', '--stats']);
    expect(JSON.parse(r.stdout)).toMatchObject({ triangles: 32, quads: 72, controlEdges: 96 });
    const fixed = run([fixture('grid-open.off'), '--scheme', 'quad-triangle', '--fixed-boundary']);
    expect(fixed.status).toBe(0);
    expect(fixed.stdout.split('\n').find((l) => l.startsWith('0 0 '))).toBeDefined();
    const ds = run([fixture('cube.off'), '--scheme', 'doo-sabin', '--stats']);
    expect(JSON.parse(ds.stdout).controlEdges).toBeUndefined();
  });

  it('bad rule files and bad weights: exit 1 with one error line naming the rule file', () => {
    const dir = mkdtempSync(join(tmpdir(), 'subdiv-rules-'));
    const evil = join(dir, 'evil.json');
    writeFileSync(
      evil,
      JSON.stringify({ host: 'pqq', vertex: { self: 'process(3)', neighbour: 0 }, edge: { end: 0.5, wing: 0 } }),
    );
    let r = run([fixture('cube.off'), '--rule', evil]);
    expect(r.status).toBe(1);
    expect(r.stderr).toMatch(
      /^error: .*evil\.json: rule set: vertex\.self: expression "process\(3\)": unknown name "process"/,
    );
    expect(r.stderr.trim().split('\n')).toHaveLength(1);
    const sum = join(dir, 'sum.json');
    writeFileSync(
      sum,
      JSON.stringify({ host: 'pqq', vertex: { self: 0.9, neighbour: 0 }, edge: { end: 0.5, wing: 0 } }),
    );
    r = run([fixture('cube.off'), '--rule', sum]);
    expect(r.status).toBe(1);
    expect(r.stderr).toBe(`error: ${sum}: custom rules: the vertex rule at valence 3 sums to 0.9, not 1\n`);
    r = run([fixture('cube.off'), '--scheme', 'custom']);
    expect(r.status).toBe(2);
    expect(r.stderr).toMatch(/--scheme custom needs --rule FILE\.json/);
    r = run([fixture('cube.off'), '--scheme', 'loop', '--rule', sum]);
    expect(r.status).toBe(2);
  });
});
