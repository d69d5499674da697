/** Subdivide (+1 level), Reset, and a scrubber over the computed levels 0..N. */
import type { ViewerState } from '../viewer/subdiv-viewer';
import { button, el, section, uniqueId } from './dom';
import { faceTypes } from './facts-panel';
import { LevelTable } from './level-table';

export interface LevelPanelHandlers {
  onSubdivide: () => void;
  onReset: () => void;
  onLevel: (level: number) => void;
}

export class LevelPanel {
  readonly element: HTMLElement;
  private readonly subdivide: HTMLButtonElement;
  private readonly reset: HTMLButtonElement;
  private readonly range: HTMLInputElement;
  private readonly label: HTMLOutputElement;
  /** What a screen reader hears after a step or a scrub: the level's faces and genus. */
  private readonly status: HTMLElement;
  private readonly table = new LevelTable();

  constructor(handlers: LevelPanelHandlers) {
    this.subdivide = button('Subdivide', 'controls.subdivide', handlers.onSubdivide, 'Compute one more level (S)');
    this.subdivide.setAttribute('aria-keyshortcuts', 's');
    this.reset = button('Reset', 'controls.reset', handlers.onReset, 'Drop computed levels, back to the control mesh');
    const rangeId = uniqueId('level');
    this.range = el('input', {
      testId: 'controls.level',
      attrs: { type: 'range', min: '0', max: '0', step: '1', value: '0', id: rangeId },
    });
    this.range.addEventListener('input', () => handlers.onLevel(Number(this.range.value)));
    this.label = el('output', { testId: 'controls.level-label', attrs: { for: rangeId } });
    this.status = el('p', { testId: 'controls.level-status', className: 'visually-hidden', attrs: { role: 'status' } });
    this.element = section(
      'Levels',
      'level-panel',
      el('div', { className: 'row' }, this.subdivide, this.reset),
      el('label', { attrs: { for: rangeId }, text: 'Level' }),
      el('div', { className: 'row' }, this.range, this.label),
      this.status,
      this.table.element,
    );
  }

  update(state: ViewerState): void {
    const loaded = state.levelCount > 0;
    this.subdivide.disabled = !loaded || state.busy !== null;
    this.reset.disabled = !loaded || state.levelCount < 2;
    const max = Math.max(0, state.levelCount - 1);
    this.range.max = String(max);
    this.range.value = String(state.level);
    this.range.disabled = max === 0;
    this.range.setAttribute('aria-valuetext', `Level ${state.level} of ${max}`);
    this.label.textContent = loaded ? `${state.level} / ${max}` : '–';
    const said =
      state.facts && !state.busy ? `Level ${state.level}: ${faceTypes(state.facts)}, genus ${state.facts.genus}` : '';
    this.table.update(state);
    // Only a change: a live region reads each new text.
    if (said && said !== this.status.textContent) this.status.textContent = said;
  }
}
