/**
 * Basis function panel: switches the view on, takes a control vertex's
 * number from the keyboard, and shows the colour bar of its influence with
 * the largest weight and how many of the level's vertices it reaches.
 */
import type { BasisState } from '../teach/basis-view';
import { button, el, section, vertexField } from './dom';
import { influenceEnds, labelledInfluenceBar } from './influence-bar';

export interface BasisPanelHandlers {
  onPicking: (on: boolean) => void;
  onVertex: (vertex: number) => void;
}

export class BasisPanel {
  readonly element: HTMLElement;
  private readonly toggle: HTMLButtonElement;
  private readonly message: HTMLElement;
  private readonly row: HTMLElement;
  private readonly vertex: HTMLInputElement;
  private readonly legend: HTMLElement;
  private readonly low: HTMLElement;
  private readonly high: HTMLElement;
  private readonly reach: HTMLElement;
  private picking = false;

  constructor(handlers: BasisPanelHandlers) {
    this.toggle = button(
      'Basis function',
      'basis.toggle',
      () => handlers.onPicking(!this.picking),
      "Colour the surface by a control vertex's influence",
    );
    this.message = el('p', { testId: 'basis.message', className: 'hint' });
    const field = vertexField('Control vertex', 'basis.vertex', handlers.onVertex);
    this.vertex = field.input;
    this.row = field.row;
    const bar = labelledInfluenceBar('basis');
    this.low = bar.low;
    this.high = bar.high;
    this.reach = el('p', { testId: 'basis.reach' });
    this.legend = el('div', { testId: 'basis.legend' }, bar.element, this.reach);
    this.element = section('Basis function', 'basis-panel', this.toggle, this.message, this.row, this.legend);
  }

  update(state: BasisState): void {
    this.picking = state.picking;
    this.toggle.disabled = !state.available;
    this.toggle.setAttribute('aria-pressed', String(state.picking));
    this.message.textContent = state.message;
    this.message.hidden = state.message === '';
    this.row.hidden = !state.picking;
    this.vertex.max = String(Math.max(0, state.controlVertices - 1));
    const shown = state.shown;
    this.legend.hidden = !shown;
    if (!shown) return;
    if (document.activeElement !== this.vertex) this.vertex.value = String(shown.vertex);
    [this.low.textContent, this.high.textContent] = influenceEnds(shown.min, shown.max);
    this.reach.textContent =
      `Control vertex ${shown.vertex} reaches ${shown.reached} of the ${shown.count} vertices of level ${shown.level}` +
      ` (largest weight ${shown.max.toFixed(4)}).`;
  }
}
