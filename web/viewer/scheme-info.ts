/** What the app says about each scheme the core offers. */
import type { SchemeName } from '../core/mesh';
import type { RuleHost } from '../core/rule-set';

export interface SchemeInfo {
  /** Name shown in the picker. */
  label: string;
  /** One line for the picker's description. */
  description: string;
  /** The scheme refuses faces other than triangles (the core's `not_triangles`). */
  needsTriangles: boolean;
  /** The scheme steps with the rules panel's rule set. */
  needsRules?: boolean;
}

const INFO: Record<SchemeName, SchemeInfo> = {
  'catmull-clark': {
    label: 'Catmull-Clark',
    description: 'Quad refinement (PQQ): every face splits into quads; smooth, approximating. Any polygons.',
    needsTriangles: false,
  },
  loop: {
    label: 'Loop',
    description: 'Triangle refinement (PTQ): each triangle splits into four; smooth, approximating. Needs triangles.',
    needsTriangles: true,
  },
  'doo-sabin': {
    label: 'Doo-Sabin',
    description: 'Dual quad refinement (DQQ): new faces for every face, edge and vertex; cuts corners. Any polygons.',
    needsTriangles: false,
  },
  sqrt3: {
    label: '√3 (Kobbelt)',
    description: 'Each triangle gets a centre vertex, then old edges flip; triples faces per step. Needs triangles.',
    needsTriangles: true,
  },
  'quad-triangle': {
    label: 'Quad/Triangle',
    description: 'Stam & Loop: triangles and quads refined together; after one step only triangles and quads.',
    needsTriangles: false,
  },
  linear: {
    label: 'Linear (PQQ)',
    description: 'Quad refinement with averaging only: centroids and midpoints, vertices stay. Any polygons.',
    needsTriangles: false,
  },
  'linear-tri': {
    label: 'Linear (PTQ)',
    description: 'Midpoint split of triangles; the surface does not move. Needs triangles.',
    needsTriangles: true,
  },
  custom: {
    label: 'Custom rules',
    description: 'Your own weights on a refinement host (PQQ, PTQ, DQQ or √3): edit them in the Rules panel.',
    needsTriangles: false,
    needsRules: true,
  },
};

/** Every scheme, in the order the core lists them. */
export const SCHEME_NAMES = Object.keys(INFO) as readonly SchemeName[];

/** True when `name` is one of {@link SCHEME_NAMES}. */
export function isSchemeName(name: string): name is SchemeName {
  return Object.hasOwn(INFO, name);
}

/** Info for a scheme name; names the app does not know yet get a neutral entry. */
export function schemeInfo(name: SchemeName | string): SchemeInfo {
  return isSchemeName(name)
    ? INFO[name]
    : { label: name, description: `The core's ${name} scheme.`, needsTriangles: false };
}

/** The host's short name: PQQ, PTQ, DQQ, √3. */
export function hostLabel(host: RuleHost): string {
  return host === 'sqrt3' ? '√3' : host.toUpperCase();
}

/** The host refuses faces other than triangles. */
export function hostNeedsTriangles(host: RuleHost): boolean {
  return host === 'ptq' || host === 'sqrt3';
}
