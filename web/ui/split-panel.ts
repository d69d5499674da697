/**
 * Split, then smooth panel: a slider from the shown level's split alone (0)
 * to its smoothed points (1), and a button that plays the step.
 */
import type { SplitState } from '../teach/split-smooth';
import { button, el, section, uniqueId } from './dom';

export interface SplitPanelHandlers {
  onT: (t: number) => void;
  onAnimate: () => void;
}

export class SplitPanel {
  readonly element: HTMLElement;
  private readonly slider: HTMLInputElement;
  private readonly value: HTMLOutputElement;
  private readonly play: HTMLButtonElement;
  private readonly message: HTMLElement;

  constructor(handlers: SplitPanelHandlers) {
    const id = uniqueId('split');
    this.slider = el('input', {
      testId: 'split.t',
      attrs: { id, type: 'range', min: '0', max: '1', step: '0.01', value: '1' },
    });
    this.slider.addEventListener('input', () => handlers.onT(Number(this.slider.value)));
    this.value = el('output', { testId: 'split.value', attrs: { for: id } });
    this.play = button('Play the step', 'split.play', handlers.onAnimate, 'From the split to the smoothed level');
    this.message = el('p', { testId: 'split.message', className: 'hint' });
    this.element = section(
      'Split, then smooth',
      'split-panel',
      el('p', {
        className: 'hint',
        text: 'A step splits the faces (0: the points of the split alone), then averages them (1).',
      }),
      el('label', { attrs: { for: id }, text: 'Split → smoothed' }),
      el('div', { className: 'row' }, this.slider, this.value),
      this.play,
      this.message,
    );
  }

  update(state: SplitState): void {
    this.slider.disabled = !state.available;
    this.play.disabled = !state.available || state.animating;
    if (document.activeElement !== this.slider || state.animating) this.slider.value = String(state.t);
    this.value.textContent = state.t.toFixed(2);
    this.message.textContent = state.message;
    this.message.hidden = state.message === '';
  }
}
