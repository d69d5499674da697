/**
 * Stencils panel: switches the stencil inspector on, takes a vertex number
 * from the keyboard, and shows the inspected vertex's kind, valence or
 * degree, the scheme's formula and its parents with their weights, with
 * the sums that prove them (Σ w = 1, Σ w·p = p).
 */
import { type InspectorState, stencilKindText } from '../teach/stencil-inspector';
import { button, el, section, vertexField } from './dom';

export interface StencilPanelHandlers {
  onInspecting: (on: boolean) => void;
  onVertex: (vertex: number) => void;
}

function point(p: readonly number[]): string {
  return `(${p.map((x) => x.toFixed(4)).join(', ')})`;
}

export class StencilPanel {
  readonly element: HTMLElement;
  private readonly inspect: HTMLButtonElement;
  private readonly message: HTMLElement;
  private readonly vertex: HTMLInputElement;
  private readonly details: HTMLElement;
  private inspecting = false;
  private shown: InspectorState['stencil'] = null;

  constructor(handlers: StencilPanelHandlers) {
    this.inspect = button(
      'Inspect stencils',
      'stencils.inspect',
      () => handlers.onInspecting(!this.inspecting),
      'Click a vertex to see its parents and weights (W)',
    );
    this.inspect.setAttribute('aria-keyshortcuts', 'w');
    this.message = el('p', { testId: 'stencils.message', className: 'hint' });
    const field = vertexField('Vertex', 'stencils.vertex', handlers.onVertex);
    this.vertex = field.input;
    this.details = el('div', {
      testId: 'stencils.details',
      className: 'stencil-details',
      attrs: { 'aria-live': 'polite' },
    });
    this.element = section('Stencils', 'stencil-panel', this.inspect, this.message, field.row, this.details);
  }

  update(state: InspectorState): void {
    this.inspecting = state.inspecting;
    this.inspect.disabled = !state.available;
    this.inspect.setAttribute('aria-pressed', String(state.inspecting));
    this.message.textContent = state.message;
    this.message.hidden = state.message === '';
    const row = this.vertex.parentElement as HTMLElement;
    row.hidden = !state.inspecting || state.level < 1;
    this.vertex.max = String(Math.max(0, state.vertexCount - 1));
    const s = state.stencil;
    this.details.hidden = !s;
    // Rebuilt only for another vertex: the region is live, and a screen reader would read it again.
    if (s === this.shown) return;
    this.shown = s;
    if (!s) {
      this.details.replaceChildren();
      return;
    }
    if (document.activeElement !== this.vertex) this.vertex.value = String(s.vertex);
    const rows = s.parents.map((p, i) =>
      el('tr', {}, el('td', { text: String(p.vertex) }), el('td', { text: s.weightTexts[i] })),
    );
    this.details.replaceChildren(
      el('p', { testId: 'stencils.title', className: 'stencil-title', text: `Vertex ${s.vertex} of level ${s.level}` }),
      el('p', { testId: 'stencils.kind', text: stencilKindText(s) }),
      ...(s.formula ? [el('p', { testId: 'stencils.formula', className: 'stencil-formula', text: s.formula })] : []),
      el(
        'table',
        { testId: 'stencils.parents', className: 'stencil-parents' },
        el('thead', {}, el('tr', {}, el('th', { text: `Level ${s.level - 1} vertex` }), el('th', { text: 'Weight' }))),
        el('tbody', {}, ...rows),
      ),
      el('p', { testId: 'stencils.sum', text: `Σ w = ${Number(s.sum.toFixed(12))}` }),
      el('p', {
        testId: 'stencils.check',
        text: `Σ w·p = ${point(s.combination)}; the vertex is at ${point(s.position)}`,
      }),
    );
  }
}
