/**
 * `subdiv halfedges`' output: the halfedge table as JSON, one halfedge per
 * line so that a student can read it and diff it against their own.
 */
import type { HalfedgeTable } from '../core/halfedges';

/** What the table is of, printed before it. */
export interface HalfedgeHeader {
  scheme?: string;
  levels?: number;
  vertices: number;
  faces: number;
}

/**
 * `{ ...header, halfedges, borderHalfedges, table: [{ h, next, prev,
 * opposite, vertex, face }] }`, face null on the border; valid JSON.
 */
export function halfedgeJson(header: HalfedgeHeader, t: HalfedgeTable): string {
  const rows: string[] = [];
  let border = 0;
  for (let h = 0; h < t.next.length; h++) {
    const face = t.face[h] < 0 ? null : t.face[h];
    if (face === null) border++;
    const row = { h, next: t.next[h], prev: t.prev[h], opposite: t.opposite[h], vertex: t.target[h], face };
    rows.push(`    ${JSON.stringify(row)}`);
  }
  const head = { ...header, halfedges: t.next.length, borderHalfedges: border };
  const fields = Object.entries(head).map(([key, value]) => `  ${JSON.stringify(key)}: ${JSON.stringify(value)},`);
  return `{\n${fields.join('\n')}\n  "table": [\n${rows.join(',\n')}\n  ]\n}\n`;
}
