/**
 * Progress of a long load or step, shown only after it has lasted about
 * 200 ms (shorter work would just flicker), with elapsed time and Cancel.
 * A WASM call cannot report progress, so the bar is indeterminate.
 */
import type { BusyState } from '../viewer/subdiv-viewer';
import { button, el } from './dom';

export const PROGRESS_DELAY_MS = 200;

export class ProgressOverlay {
  readonly element: HTMLElement;
  private readonly label: HTMLElement;
  private readonly elapsed: HTMLElement;
  private busy: BusyState | null = null;
  private timer = 0;

  constructor(onCancel: () => void) {
    this.label = el('span', { testId: 'progress.label' });
    this.elapsed = el('span', { testId: 'progress.elapsed', className: 'progress-elapsed' });
    this.element = el(
      'div',
      { testId: 'progress', className: 'progress-overlay', attrs: { role: 'status' } },
      el('div', {}, this.label, ' ', this.elapsed),
      el('progress', { attrs: { 'aria-label': 'Working' } }),
      button('Cancel', 'progress.cancel', onCancel, 'Stop this step; computed levels stay (Esc)'),
    );
    this.element.hidden = true;
  }

  /** Follows the viewer's busy state. */
  update(busy: BusyState | null): void {
    if (busy === this.busy) return;
    this.busy = busy;
    clearInterval(this.timer);
    if (!busy) {
      this.element.hidden = true;
      return;
    }
    this.label.textContent = busy.label;
    const tick = () => {
      const ms = performance.now() - busy.since;
      if (ms < PROGRESS_DELAY_MS) return;
      this.element.hidden = false;
      this.elapsed.textContent = `${(ms / 1000).toFixed(1)} s`;
    };
    this.timer = window.setInterval(tick, 100);
    tick();
  }

  get visible(): boolean {
    return !this.element.hidden;
  }
}
