/**
 * Rule sets for the `custom` scheme: a refinement host of CGAL's
 * Subdivision_method_3 and the weights of its mask, as a small JSON file.
 * Weights are numbers or formulas (strings, see expression.ts) in the
 * valence `n`, the face degree `k` and, for Doo-Sabin-like corner rules, the
 * corner offset `j`. Before a rule set crosses to C++ it is evaluated into
 * tables (valences / degrees 3..max), so no code is compiled at run time; the
 * C++ core checks that the weights are finite and that every stencil sums to 1.
 *
 * File format (`public/rules/*.json`):
 * ```json
 * {
 *   "format": "subdivlab-rules",
 *   "version": 1,
 *   "name": "Loop",
 *   "host": "ptq",
 *   "vertex": { "self": W(n), "neighbour": W(n), "face": W(n) },
 *   "edge": { "end": W, "wing": W },
 *   "corner": { "self": W(k), "other": W(k, j) },
 *   "border": { "vertex": [W, W, W], "edge": [W, W, W, W], "corner": [W, W] }
 * }
 * ```
 * where W is a number or a formula string, and a valence-dependent W(n) may
 * also be an object of per-valence values with a default:
 * `{ "6": "1/16", "default": "3/(8*n)" }`.
 *
 * Which parts a host reads (others must be absent):
 * - `pqq` (Catmull-Clark-like): vertex (self, neighbour, face: weight of each
 *   incident face centroid), edge (end: each endpoint, wing: each adjacent face
 *   centroid), border.vertex, border.edge.
 * - `ptq` (Loop-like, triangles): vertex (self, neighbour), edge (wing: each
 *   vertex opposite the edge), border.vertex, border.edge.
 * - `sqrt3` (triangles): vertex (self, neighbour), border.vertex and
 *   border.edge (on the steps that refine the border: the new point nearer a,
 *   the other mirrored).
 * - `dqq` (Doo-Sabin-like): corner (self: the corner's own vertex, other: the
 *   vertex j = 1..k-1 steps after it around the face), border.corner (a corner
 *   point on a border edge: own vertex, other end).
 * Border weights run along the border: vertex = [previous, self, next],
 * edge = [before a, a, b, after b]. `border` may be left out: pqq and ptq
 * then use the cubic B-spline rule ([1/8, 3/4, 1/8], midpoints), sqrt3 CGAL's
 * ([4, 19, 4]/27, [1, 16, 10, 0]/27), dqq Chaikin's ([3/4, 1/4]).
 */
import { parseExpression } from './expression';
import { quotedValue } from './quoted-value';
import { SubdivError } from './subdiv-error';

/** Refinement hosts of CGAL's Subdivision_method_3. */
export type RuleHost = 'pqq' | 'ptq' | 'dqq' | 'sqrt3';

/** A weight: a number or a formula. */
export type Weight = number | string;

/** A weight that may depend on the valence: one formula, or per-valence values with a default. */
export type ValenceWeight = Weight | { [valence: string]: Weight };

/** A rule set as stored in a file (see the module comment for the format). */
export interface RuleSet {
  format?: 'subdivlab-rules';
  version?: 1;
  name?: string;
  description?: string;
  host: RuleHost;
  vertex?: { self: ValenceWeight; neighbour: ValenceWeight; face?: ValenceWeight };
  edge?: { end: Weight; wing: Weight };
  corner?: { self: Weight; other: Weight };
  border?: {
    vertex?: [Weight, Weight, Weight];
    edge?: [Weight, Weight, Weight, Weight];
    corner?: [Weight, Weight];
  };
}

/** A rule set evaluated into tables: what crosses to C++ (Custom_rules). */
export interface CompiledRules {
  host: RuleHost;
  /** Valence of the first row of `vertex`. */
  firstValence: number;
  /** [self, neighbour, face] for valences firstValence, firstValence + 1, ... */
  vertex: number[];
  /** [end, wing]. */
  edge: [number, number];
  /** Degree of the first row of `corner`. */
  firstDegree: number;
  /** Rows for degrees firstDegree, firstDegree + 1, ...: row k holds k weights. */
  corner: number[];
  borderVertex: [number, number, number];
  borderEdge: [number, number, number, number];
  borderCorner: [number, number];
}

/** Names of the rule sets shipped in public/rules/NAME.json. */
export const RULE_PRESETS = ['catmull-clark', 'loop', 'doo-sabin', 'sqrt3', 'improved-loop', 'linear'] as const;
export type RulePresetName = (typeof RULE_PRESETS)[number];

const HOSTS: readonly RuleHost[] = ['pqq', 'ptq', 'dqq', 'sqrt3'];
const FIRST = 3;
/** Default table size: valences and face degrees 3..64. */
export const DEFAULT_MAX_VALENCE = 64;
/** Largest table the compiler builds (the core checks coverage anyway). */
const MAX_TABLE = 4096;
const MAX_DEGREE_TABLE = 1024;

function refuse(where: string, message: string): never {
  throw new SubdivError('invalid_argument', `rule set: ${where}: ${message}`);
}

function isRecord(x: unknown): x is Record<string, unknown> {
  return typeof x === 'object' && x !== null && !Array.isArray(x);
}

function checkKeys(where: string, obj: Record<string, unknown>, allowed: readonly string[]): void {
  for (const key of Object.keys(obj)) {
    if (!allowed.includes(key)) refuse(where, `unknown key "${key}" (expected ${allowed.join(', ')})`);
  }
}

/** Checks one weight: a finite number or a formula in `vars`. */
function checkWeight(where: string, w: unknown, vars: readonly string[]): Weight {
  if (typeof w === 'number') {
    if (!Number.isFinite(w)) refuse(where, `${w} is not a finite number`);
    return w;
  }
  if (typeof w === 'string') {
    try {
      parseExpression(w, vars);
    } catch (error) {
      if (error instanceof SubdivError) refuse(where, error.message);
      throw error;
    }
    return w;
  }
  return refuse(where, `expected a number or a formula string, got ${w === null ? 'null' : typeof w}`);
}

function checkValenceWeight(where: string, w: unknown, vars: readonly string[]): ValenceWeight {
  if (!isRecord(w)) return checkWeight(where, w, vars);
  const out: Record<string, Weight> = {};
  for (const [key, value] of Object.entries(w)) {
    if (key !== 'default' && !/^[1-9]\d*$/.test(key)) {
      refuse(where, `key "${key}" is neither a valence (a whole number) nor "default"`);
    }
    out[key] = checkWeight(`${where}["${key}"]`, value, vars);
  }
  return out;
}

function checkTuple<N extends number>(where: string, w: unknown, length: N): Weight[] {
  if (!Array.isArray(w) || w.length !== length) refuse(where, `expected an array of ${length} weights`);
  return w.map((x, i) => checkWeight(`${where}[${i}]`, x, []));
}

/**
 * Checks parsed JSON (or a rule set built in code) and returns it typed.
 * Refuses unknown keys, parts the host does not read, missing parts it
 * needs, and formulas that do not parse. Throws SubdivError('invalid_argument').
 */
export function parseRuleSet(json: unknown): RuleSet {
  if (!isRecord(json)) refuse('file', 'expected a JSON object');
  checkKeys('file', json, ['format', 'version', 'name', 'description', 'host', 'vertex', 'edge', 'corner', 'border']);
  if (json.format !== undefined && json.format !== 'subdivlab-rules') {
    refuse('format', `expected "subdivlab-rules", got ${quotedValue(json.format)}`);
  }
  if (json.version !== undefined && json.version !== 1)
    refuse('version', `expected 1, got ${quotedValue(json.version)}`);
  for (const key of ['name', 'description'] as const) {
    if (json[key] !== undefined && typeof json[key] !== 'string') refuse(key, 'expected a string');
  }
  const host = json.host;
  if (typeof host !== 'string' || !HOSTS.includes(host as RuleHost)) {
    refuse('host', `expected one of ${HOSTS.join(', ')}, got ${quotedValue(host)}`);
  }
  const h = host as RuleHost;
  const out: RuleSet = { host: h };
  if (json.format !== undefined) out.format = 'subdivlab-rules';
  if (json.version !== undefined) out.version = 1;
  if (typeof json.name === 'string') out.name = json.name;
  if (typeof json.description === 'string') out.description = json.description;

  const needs = {
    vertex: h !== 'dqq',
    edge: h === 'pqq' || h === 'ptq',
    corner: h === 'dqq',
  };
  for (const part of ['vertex', 'edge', 'corner'] as const) {
    if (needs[part] && json[part] === undefined) refuse(part, `the ${h} host needs a ${part} rule`);
    if (!needs[part] && json[part] !== undefined) refuse(part, `the ${h} host has no ${part} rule`);
  }
  if (json.vertex !== undefined) {
    const v = json.vertex;
    if (!isRecord(v)) refuse('vertex', 'expected an object { self, neighbour, face? }');
    checkKeys('vertex', v, h === 'pqq' ? ['self', 'neighbour', 'face'] : ['self', 'neighbour']);
    if (v.self === undefined || v.neighbour === undefined) refuse('vertex', 'needs "self" and "neighbour"');
    out.vertex = {
      self: checkValenceWeight('vertex.self', v.self, ['n']),
      neighbour: checkValenceWeight('vertex.neighbour', v.neighbour, ['n']),
    };
    if (v.face !== undefined) out.vertex.face = checkValenceWeight('vertex.face', v.face, ['n']);
  }
  if (json.edge !== undefined) {
    const e = json.edge;
    if (!isRecord(e)) refuse('edge', 'expected an object { end, wing }');
    checkKeys('edge', e, ['end', 'wing']);
    if (e.end === undefined || e.wing === undefined) refuse('edge', 'needs "end" and "wing"');
    out.edge = { end: checkWeight('edge.end', e.end, []), wing: checkWeight('edge.wing', e.wing, []) };
  }
  if (json.corner !== undefined) {
    const c = json.corner;
    if (!isRecord(c)) refuse('corner', 'expected an object { self, other }');
    checkKeys('corner', c, ['self', 'other']);
    if (c.self === undefined || c.other === undefined) refuse('corner', 'needs "self" and "other"');
    out.corner = {
      self: checkWeight('corner.self', c.self, ['k']),
      other: checkWeight('corner.other', c.other, ['k', 'j']),
    };
  }
  if (json.border !== undefined) {
    const b = json.border;
    if (!isRecord(b)) refuse('border', 'expected an object');
    checkKeys('border', b, h === 'dqq' ? ['corner'] : ['vertex', 'edge']);
    out.border = {};
    if (b.vertex !== undefined)
      out.border.vertex = checkTuple('border.vertex', b.vertex, 3) as [Weight, Weight, Weight];
    if (b.edge !== undefined)
      out.border.edge = checkTuple('border.edge', b.edge, 4) as [Weight, Weight, Weight, Weight];
    if (b.corner !== undefined) out.border.corner = checkTuple('border.corner', b.corner, 2) as [Weight, Weight];
  }
  return out;
}

/** Parses the text of a rule file (JSON) and checks it (see {@link parseRuleSet}). */
export function parseRuleSetText(text: string): RuleSet {
  let json: unknown;
  try {
    json = JSON.parse(text);
  } catch (error) {
    refuse('file', `not valid JSON (${(error as Error).message})`);
  }
  return parseRuleSet(json);
}

/** The text of a rule file for `rules` (pretty-printed JSON, format and version filled in). */
export function ruleSetToText(rules: RuleSet): string {
  return `${JSON.stringify({ format: 'subdivlab-rules', version: 1, ...rules }, null, 2)}\n`;
}

function evaluateWeight(w: Weight, vars: Record<string, number>): number {
  return typeof w === 'number' ? w : parseExpression(w, Object.keys(vars)).evaluate(vars);
}

function evaluateValenceWeight(w: ValenceWeight | undefined, n: number, where: string): number {
  if (w === undefined) return 0;
  if (typeof w === 'number' || typeof w === 'string') return evaluateWeight(w, { n });
  const chosen = w[String(n)] ?? w.default;
  if (chosen === undefined) refuse(where, `no value for valence ${n} and no "default"`);
  return evaluateWeight(chosen, { n });
}

/** Options of {@link compileRuleSet}. */
export interface CompileLimits {
  /** Largest valence the vertex table covers (default 64). */
  maxValence?: number;
  /** Largest face degree the corner table covers (default 64). */
  maxDegree?: number;
}

/**
 * Evaluates a rule set into the tables the core takes (valences and face
 * degrees 3..max). Values are not checked here (the core refuses non-finite
 * weights and stencils that do not sum to 1, naming the rule and valence).
 */
export function compileRuleSet(input: RuleSet, limits: CompileLimits = {}): CompiledRules {
  const rules = parseRuleSet(input);
  const clamp = (x: number | undefined) => Math.min(MAX_TABLE, Math.max(FIRST, Math.floor(x ?? DEFAULT_MAX_VALENCE)));
  const maxValence = clamp(limits.maxValence);
  // A k-gon's row has k weights: keep the corner table to about 500k numbers.
  const maxDegree = Math.min(clamp(limits.maxDegree), MAX_DEGREE_TABLE);
  const h = rules.host;
  const compiled: CompiledRules = {
    host: h,
    firstValence: FIRST,
    vertex: [],
    edge: [0.5, 0],
    firstDegree: FIRST,
    corner: [],
    borderVertex: h === 'sqrt3' ? [4 / 27, 19 / 27, 4 / 27] : [1 / 8, 3 / 4, 1 / 8],
    borderEdge: h === 'sqrt3' ? [1 / 27, 16 / 27, 10 / 27, 0] : [0, 0.5, 0.5, 0],
    borderCorner: [0.75, 0.25],
  };
  if (rules.vertex) {
    const v = rules.vertex;
    for (let n = FIRST; n <= maxValence; n++) {
      compiled.vertex.push(
        evaluateValenceWeight(v.self, n, 'vertex.self'),
        evaluateValenceWeight(v.neighbour, n, 'vertex.neighbour'),
        evaluateValenceWeight(v.face, n, 'vertex.face'),
      );
    }
  }
  if (rules.edge) compiled.edge = [evaluateWeight(rules.edge.end, {}), evaluateWeight(rules.edge.wing, {})];
  if (rules.corner) {
    const self = parseExpressionOrNumber(rules.corner.self, ['k']);
    const other = parseExpressionOrNumber(rules.corner.other, ['k', 'j']);
    for (let k = FIRST; k <= maxDegree; k++) {
      compiled.corner.push(self({ k }));
      for (let j = 1; j < k; j++) compiled.corner.push(other({ k, j }));
    }
  }
  const b = rules.border;
  if (b?.vertex) compiled.borderVertex = b.vertex.map((w) => evaluateWeight(w, {})) as [number, number, number];
  if (b?.edge) compiled.borderEdge = b.edge.map((w) => evaluateWeight(w, {})) as [number, number, number, number];
  if (b?.corner) compiled.borderCorner = b.corner.map((w) => evaluateWeight(w, {})) as [number, number];
  return compiled;
}

function parseExpressionOrNumber(w: Weight, vars: readonly string[]): (values: Record<string, number>) => number {
  if (typeof w === 'number') return () => w;
  const e = parseExpression(w, vars);
  return (values) => e.evaluate(values);
}

/**
 * Table sizes a mesh needs: its largest vertex valence (+1 for border
 * vertices) and face degree, and at least the default 64 — the refinement
 * never creates a valence or degree above those and 6.
 */
export function compileLimitsFor(faceSizes: Uint32Array, faceIndices: Uint32Array, vertexCount: number): CompileLimits {
  let maxDegree = 0;
  for (const k of faceSizes) maxDegree = Math.max(maxDegree, k);
  const corners = new Uint32Array(vertexCount);
  for (const v of faceIndices) if (v < vertexCount) corners[v]++;
  let maxCorners = 0;
  for (const c of corners) maxCorners = Math.max(maxCorners, c);
  const need = Math.max(DEFAULT_MAX_VALENCE, maxCorners + 1, maxDegree);
  return { maxValence: need, maxDegree: need };
}
