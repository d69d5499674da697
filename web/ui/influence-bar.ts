/**
 * The influence colour bar (viridis, as render/level-graphics.ts colours a
 * surface by a value: a basis function's weights, a result's errors, the
 * distance between side-by-side panes), for the app's panels and the
 * `<subdiv-viewer>` caption.
 */
import { INFLUENCE_STOPS } from '../render/level-graphics';
import { el } from './dom';

/** A bar from the least value (dark purple, left) to the largest (yellow, right), described by `label`. */
export function influenceBar(
  className = 'colour-bar',
  label = 'colour bar: no influence (dark) to the largest (yellow)',
): HTMLElement {
  const bar = el('div', { className, attrs: { role: 'img', 'aria-label': label } });
  bar.style.background = `linear-gradient(to right, ${INFLUENCE_STOPS.join(', ')})`;
  return bar;
}

/** The values at the bar's ends, as written under it: 0 (or a negative least value) and the largest. */
export function influenceEnds(min: number, max: number): [string, string] {
  return [min < 0 ? min.toFixed(4) : '0', max.toFixed(4)];
}

export interface LabelledBar {
  element: HTMLElement;
  /** The texts under the bar's ends (test ids `<testId>.low`, `<testId>.high`). */
  low: HTMLElement;
  high: HTMLElement;
}

/** The bar with its end values under it, for a panel. */
export function labelledInfluenceBar(testId: string, label?: string): LabelledBar {
  const low = el('span', { testId: `${testId}.low` });
  const high = el('span', { testId: `${testId}.high` });
  const element = el(
    'div',
    {},
    influenceBar('colour-bar', label),
    el('div', { className: 'row colour-bar-labels' }, low, high),
  );
  return { element, low, high };
}
