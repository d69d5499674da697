/**
 * What the app says about each scheme the core offers: the core's own table
 * (web/core/scheme-table.ts), in the shape the panels use.
 */
import type { SchemeName } from '../core/mesh';
import type { RuleHost } from '../core/rule-set';
import { SCHEME_TABLE } from '../core/scheme-table';

export interface SchemeInfo {
  /** Name shown in the picker. */
  label: string;
  /** One line for the picker's description. */
  description: string;
  /** The scheme refuses faces other than triangles (the core's `not_triangles`). */
  needsTriangles: boolean;
  /** The scheme steps with the rules panel's rule set (its host is the rule set's). */
  needsRules?: boolean;
  /** The scheme applies a mesh's tags (creases, corners, holes, border modes): Catmull-Clark and Loop. */
  creases: boolean;
}

function hostInfo(name: string) {
  return SCHEME_TABLE.hosts.find((h) => h.name === name);
}

const INFO = new Map<string, SchemeInfo>(
  SCHEME_TABLE.schemes.map((s) => [
    s.name,
    {
      label: s.label,
      description: s.description,
      needsTriangles: s.host !== null && hostInfo(s.host)?.needsTriangles === true,
      creases: s.creases,
      ...(s.host === null ? { needsRules: true } : {}),
    },
  ]),
);

/** Every scheme, in the order the core lists them. */
export const SCHEME_NAMES = SCHEME_TABLE.schemes.map((s) => s.name) as readonly SchemeName[];

/** Schemes a side-by-side pane can show: all but the custom scheme, whose rules belong to the first pane. */
export const PANE_SCHEMES = SCHEME_NAMES.filter((s) => !INFO.get(s)?.needsRules);

/** True when `name` is one of {@link SCHEME_NAMES}. */
export function isSchemeName(name: string): name is SchemeName {
  return INFO.has(name);
}

/** Info for a scheme name; names the app does not know yet get a neutral entry. */
export function schemeInfo(name: SchemeName | string): SchemeInfo {
  return (
    INFO.get(name) ?? { label: name, description: `The core's ${name} scheme.`, needsTriangles: false, creases: false }
  );
}

/** The host's short name: PQQ, PTQ, DQQ, √3. */
export function hostLabel(host: RuleHost): string {
  return hostInfo(host)?.label ?? host.toUpperCase();
}

/** The host refuses faces other than triangles. */
export function hostNeedsTriangles(host: RuleHost): boolean {
  return hostInfo(host)?.needsTriangles === true;
}

/**
 * The linear scheme on the same host as `scheme` (with `host`, the rule
 * set's for custom): its step is the split alone, numbered as the scheme's
 * own step. Null for the hosts without one (DQQ, √3, PQT).
 */
export function linearTwin(scheme: SchemeName | string, host?: RuleHost): 'linear' | 'linear-tri' | null {
  const on = scheme === 'custom' ? host : SCHEME_TABLE.schemes.find((s) => s.name === scheme)?.host;
  if (on === 'pqq') return 'linear';
  if (on === 'ptq') return 'linear-tri';
  return null;
}
