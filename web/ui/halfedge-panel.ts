/**
 * Halfedges panel: switches the halfedge explorer on, takes a halfedge's
 * number, walks next / prev / opposite / around the target vertex / around
 * the face (buttons, and the keys N P O V F while the explorer is on),
 * shows the picked halfedge's numbers and the expression that reached it
 * in CGAL's spelling for Surface_mesh and Polyhedron_3, and circulates a
 * vertex or a face. The Euler operators and √3 by hand follow in the same
 * panel (euler-panel.ts).
 */

import type { ExplorerState } from '../teach/halfedge-explorer';
import type { CirculationKind, HalfedgeMove } from '../teach/halfedge-moves';
import { button, el, section, vertexField } from './dom';
import type { EulerPanel } from './euler-panel';

export interface HalfedgePanelHandlers {
  onExploring: (on: boolean) => void;
  onHalfedge: (h: number) => void;
  onMove: (move: HalfedgeMove) => void;
  onCirculate: (kind: CirculationKind) => void;
}

/** Each move's button: its label, key and the CGAL expression it stands for (title). */
const MOVES: readonly { move: HalfedgeMove; label: string; key: string; title: string }[] = [
  { move: 'next', label: 'Next', key: 'n', title: 'next(h, m): the next halfedge of its face (N)' },
  { move: 'prev', label: 'Prev', key: 'p', title: 'prev(h, m): the previous halfedge of its face (P)' },
  { move: 'opposite', label: 'Opposite', key: 'o', title: 'opposite(h, m): the same edge the other way (O)' },
  {
    move: 'around-vertex',
    label: 'Around vertex',
    key: 'v',
    title: 'opposite(next(h, m), m): the next halfedge pointing to the same target vertex (V)',
  },
  { move: 'around-face', label: 'Around face', key: 'f', title: 'next(h, m): the next halfedge around the face (F)' },
];

export class HalfedgePanel {
  readonly element: HTMLElement;
  private readonly explore: HTMLButtonElement;
  private readonly message: HTMLElement;
  private readonly number: HTMLInputElement;
  private readonly body: HTMLElement;
  private readonly moves: HTMLButtonElement[];
  private readonly circulates: HTMLButtonElement[];
  private readonly picked: HTMLElement;
  private readonly surfaceMesh: HTMLElement;
  private readonly polyhedron: HTMLElement;
  private readonly start: HTMLElement;
  private readonly report: HTMLElement;
  private exploring = false;
  private hasPick = false;

  constructor(handlers: HalfedgePanelHandlers, euler: EulerPanel) {
    this.explore = button(
      'Explore halfedges',
      'halfedges.explore',
      () => handlers.onExploring(!this.exploring),
      'Draw every halfedge as an arrow; click one to walk from it',
    );
    this.message = el('p', { testId: 'halfedges.message', className: 'hint', attrs: { role: 'status' } });
    const field = vertexField('Halfedge', 'halfedges.number', handlers.onHalfedge);
    this.number = field.input;
    this.moves = MOVES.map(({ move, label, key, title }) => {
      const b = button(label, `halfedges.${move}`, () => handlers.onMove(move), title);
      b.setAttribute('aria-keyshortcuts', key);
      return b;
    });
    this.circulates = (['vertex', 'face'] as const).map((kind) =>
      button(
        `Circulate ${kind}`,
        `halfedges.circulate-${kind}`,
        () => handlers.onCirculate(kind),
        kind === 'vertex' ? 'Step around the target vertex and count its halfedges' : 'Step around the face',
      ),
    );
    this.picked = el('p', { testId: 'halfedges.picked' });
    this.start = el('p', { testId: 'halfedges.start', className: 'hint' });
    this.surfaceMesh = el('code', { testId: 'halfedges.surface-mesh' });
    this.polyhedron = el('code', { testId: 'halfedges.polyhedron' });
    this.report = el('p', { testId: 'halfedges.report', attrs: { 'aria-live': 'polite' } });
    this.body = el(
      'div',
      { testId: 'halfedges.body' },
      field.row,
      el('div', { className: 'row wrap', attrs: { role: 'group', 'aria-label': 'Walk' } }, ...this.moves),
      this.picked,
      this.start,
      el('p', {}, 'Surface_mesh: ', this.surfaceMesh),
      el('p', {}, 'Polyhedron_3: ', this.polyhedron),
      el('div', { className: 'row wrap', attrs: { role: 'group', 'aria-label': 'Circulate' } }, ...this.circulates),
      this.report,
      euler.element,
    );
    this.element = section('Halfedges', 'halfedge-panel', this.explore, this.message, this.body);
    // While the explorer is on, N P O V F walk (before the page's own shortcuts, outside text fields).
    document.addEventListener(
      'keydown',
      (event) => {
        if (!this.exploring || !this.hasPick || event.ctrlKey || event.metaKey || event.altKey) return;
        const target = event.target as HTMLElement | null;
        if (target?.closest('input, textarea, select, [contenteditable="true"]')) return;
        const move = MOVES.find((m) => m.key === event.key.toLowerCase());
        if (!move) return;
        event.preventDefault();
        event.stopPropagation();
        handlers.onMove(move.move);
      },
      true,
    );
  }

  update(state: ExplorerState): void {
    this.exploring = state.exploring;
    this.hasPick = state.picked !== null;
    this.explore.disabled = !state.available;
    this.explore.setAttribute('aria-pressed', String(state.exploring));
    const message = state.refusal || state.hint;
    this.message.textContent = message;
    this.message.hidden = message === '';
    this.body.hidden = !state.exploring || state.halfedgeCount === 0;
    this.number.max = String(Math.max(0, state.halfedgeCount - 1));
    const p = state.picked;
    for (const b of [...this.moves, ...this.circulates]) b.disabled = !p;
    if (p && document.activeElement !== this.number) this.number.value = String(p.h);
    this.picked.textContent = p
      ? `Halfedge ${p.h}: vertex ${p.source} → vertex ${p.target}, ${p.face >= 0 ? `face ${p.face}` : 'border'}; ` +
        `next ${p.next}, prev ${p.prev}, opposite ${p.opposite}.`
      : '';
    this.start.textContent = p && state.from !== null ? `h is halfedge ${state.from}; m is the mesh.` : '';
    this.surfaceMesh.textContent = p ? state.surfaceMesh : '';
    this.polyhedron.textContent = p ? state.polyhedron : '';
    const c = state.circulation;
    this.report.textContent = c ? (c.done ? c.report : `Circulating: ${c.visited.length + 1}…`) : '';
  }
}
