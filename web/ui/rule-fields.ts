/**
 * The weights of a rule set as the rules panel shows them: which fields a
 * rule set has (grouped by rule, named for people, with the variables each
 * formula may use), where each sits in the JSON, and field text ↔ weight.
 */
import { parseExpression } from '../core/expression';
import type { RuleSet } from '../core/rule-set';

/** One weight of the rule set: where it sits in the JSON, how it is named, which variables it may use. */
export interface WeightSpec {
  path: string[];
  label: string;
  vars: string[];
}

/** A rule's weights under one legend; `columns`: short weights side by side, else one per line (formulas). */
export interface WeightGroup {
  key: string;
  legend: string;
  specs: WeightSpec[];
  columns: boolean;
}

/** The groups of weights, in display order. */
export function weightGroups(rules: RuleSet): WeightGroup[] {
  const groups: WeightGroup[] = [];
  const h = rules.host;
  if (rules.vertex) {
    const specs: WeightSpec[] = [];
    const names: [keyof NonNullable<RuleSet['vertex']>, string][] = [
      ['self', 'the vertex'],
      ['neighbour', h === 'pqq' ? 'each edge neighbour' : 'each neighbour'],
      ['face', 'each face point'],
    ];
    for (const [part, label] of names) {
      const w = rules.vertex[part];
      if (w === undefined) continue;
      if (typeof w === 'object') {
        for (const key of Object.keys(w)) {
          const at = key === 'default' ? 'other n' : `n = ${key}`;
          specs.push({ path: ['vertex', part, key], label: `${label} (${at})`, vars: ['n'] });
        }
      } else specs.push({ path: ['vertex', part], label, vars: ['n'] });
    }
    groups.push({ key: 'vertex', legend: 'Vertex rule (valence n)', specs, columns: false });
  }
  if (rules.edge) {
    groups.push({
      key: 'edge',
      legend: 'Edge rule',
      columns: true,
      specs: [
        { path: ['edge', 'end'], label: 'each end', vars: [] },
        { path: ['edge', 'wing'], label: h === 'pqq' ? 'each face point' : 'each opposite vertex', vars: [] },
      ],
    });
  }
  if (rules.corner) {
    groups.push({
      key: 'corner',
      legend: 'Corner rule (face degree k)',
      columns: false,
      specs: [
        { path: ['corner', 'self'], label: 'own vertex', vars: ['k'] },
        { path: ['corner', 'other'], label: 'vertex j steps on', vars: ['k', 'j'] },
      ],
    });
  }
  const border = rules.border ?? {};
  const tuple = (part: 'vertex' | 'edge' | 'corner', labels: string[]) => {
    if (!border[part]) return;
    groups.push({
      key: `border ${part}`,
      legend: `Border ${part} rule`,
      columns: true,
      specs: labels.map((label, i) => ({ path: ['border', part, String(i)], label, vars: [] })),
    });
  };
  tuple('vertex', ['previous', 'the vertex', 'next']);
  tuple('edge', ['before a', 'a', 'b', 'after b']);
  tuple('corner', ['own vertex', 'other end']);
  return groups;
}

/** The value at `path` (`["vertex", "self", "6"]`) of a rule set. */
export function getAt(obj: unknown, path: readonly string[]): unknown {
  let at = obj;
  for (const key of path) at = (at as Record<string, unknown>)[key];
  return at;
}

/** Sets the value at `path` of a rule set (the parents exist). */
export function setAt(obj: unknown, path: readonly string[], value: unknown): void {
  let at = obj as Record<string, unknown>;
  for (const key of path.slice(0, -1)) at = at[key] as Record<string, unknown>;
  at[path[path.length - 1]] = value;
}

const PLAIN_NUMBER = /^[-+]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][-+]?\d+)?$/;

/** A field's text as a weight: plain numbers stay numbers, anything else is a formula. */
export function weightOf(text: string): number | string {
  const t = text.trim();
  return PLAIN_NUMBER.test(t) ? Number(t) : t;
}

/** A file name for a rule set: its name in lower case, e.g. `improved-loop.json`. */
export function ruleFileName(rules: RuleSet): string {
  const stem = (rules.name ?? '')
    .toLowerCase()
    .replace(/[^a-z0-9]+/g, '-')
    .replace(/^-+|-+$/g, '');
  return `${stem || 'rules'}.json`;
}

/** The parser's message for a formula that does not parse, or null. */
export function formulaError(text: string, vars: readonly string[]): string | null {
  if (PLAIN_NUMBER.test(text.trim())) return null;
  try {
    parseExpression(text, vars);
    return null;
  } catch (error) {
    return error instanceof Error ? error.message : String(error);
  }
}
