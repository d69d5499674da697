/**
 * The counts of every computed level side by side: vertices, edges, faces
 * and how many times the faces grew in the last step, the numbers a student
 * checks a scheme's growth rule against (×4 for Catmull-Clark and Loop,
 * ×3 for √3). The shown level's row is marked.
 */
import type { ViewerState } from '../viewer/subdiv-viewer';
import { el } from './dom';

/** "×4", "×3.08" (two decimals at most), or "–" for level 0. */
export function growthText(faces: number, previousFaces: number | undefined): string {
  if (previousFaces === undefined || previousFaces === 0) return '–';
  return `×${Number((faces / previousFaces).toFixed(2)).toLocaleString('en')}`;
}

const COLUMNS = ['Level', 'V', 'E', 'F', 'F growth'] as const;

export class LevelTable {
  readonly element: HTMLElement;
  private readonly body: HTMLTableSectionElement;

  constructor() {
    this.body = el('tbody');
    const head = el('tr', {}, ...COLUMNS.map((c) => el('th', { text: c, attrs: { scope: 'col' } })));
    const table = el(
      'table',
      { testId: 'levels.table', className: 'level-table' },
      el('caption', { className: 'visually-hidden', text: 'Vertices, edges and faces of each computed level' }),
      el('thead', {}, head),
      this.body,
    );
    const summary = el('summary', { text: 'Counts per level' });
    const details = el('details', { testId: 'levels.counts', className: 'level-counts' }, summary, table);
    details.open = true;
    this.element = details;
  }

  update(state: ViewerState): void {
    this.element.hidden = state.levelCount === 0;
    const rows = state.levelFacts.map((f, k) => {
      const cells = [
        String(k),
        f.vertices.toLocaleString('en'),
        f.edges.toLocaleString('en'),
        f.faces.toLocaleString('en'),
        growthText(f.faces, state.levelFacts[k - 1]?.faces),
      ];
      const row = el('tr', { testId: `levels.row.${k}` }, ...cells.map((text) => el('td', { text })));
      if (k === state.level) {
        row.className = 'shown';
        row.setAttribute('aria-current', 'true');
      }
      return row;
    });
    this.body.replaceChildren(...rows);
  }
}
