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

/**
 * A count as the table shows it: with thousands separators below a
 * million ("999,999"), in millions from there ("4.27 M", "273.2 M"), where
 * three columns of seven digits and more would push the growth factor out
 * of the panel; the facts panel and the cell's tooltip keep every digit.
 */
export function countText(n: number): string {
  if (n < 1e6) return n.toLocaleString('en');
  return `${Number((n / 1e6).toPrecision(n < 1e8 ? 3 : 4)).toLocaleString('en')} M`;
}

const COLUMNS = ['Level', 'V', 'E', 'F', 'F growth'] as const;

export class LevelTable {
  readonly element: HTMLElement;
  private readonly body: HTMLTableSectionElement;
  /** Scrolls the table sideways when its numbers are wider than the panel (ten million faces and up). */
  private readonly scroller: HTMLElement;

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
    this.scroller = el(
      'div',
      {
        testId: 'levels.table-scroll',
        className: 'level-table-scroll',
        attrs: { role: 'group', 'aria-label': 'Counts per level' },
      },
      table,
    );
    const summary = el('summary', { text: 'Counts per level' });
    const details = el('details', { testId: 'levels.counts', className: 'level-counts' }, summary, this.scroller);
    details.open = true;
    this.element = details;
  }

  update(state: ViewerState): void {
    this.element.hidden = state.levelCount === 0;
    const rows = state.levelFacts.map((f, k) => {
      const counts = [f.vertices, f.edges, f.faces].map((n) =>
        el('td', { text: countText(n), attrs: { title: n.toLocaleString('en') } }),
      );
      const row = el(
        'tr',
        { testId: `levels.row.${k}` },
        el('td', { text: String(k) }),
        ...counts,
        el('td', { text: growthText(f.faces, state.levelFacts[k - 1]?.faces) }),
      );
      if (k === state.level) {
        row.className = 'shown';
        row.setAttribute('aria-current', 'true');
      }
      return row;
    });
    this.body.replaceChildren(...rows);
    // A keyboard reaches a region it has to scroll; one that fits is no stop on the way.
    requestAnimationFrame(() => {
      if (this.scroller.scrollWidth > this.scroller.clientWidth) this.scroller.tabIndex = 0;
      else this.scroller.removeAttribute('tabindex');
    });
  }
}
