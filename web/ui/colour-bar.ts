/**
 * The influence colour bar (dark purple to yellow, as level-graphics
 * colours the surface), with the values at its two ends: the basis
 * function's weights, the distances between side-by-side panes.
 */
import { INFLUENCE_STOPS } from '../render/level-graphics';
import { el } from './dom';

export interface ColourBar {
  element: HTMLElement;
  low: HTMLElement;
  high: HTMLElement;
}

/** A bar described to screen readers as `label`; `testId` names its end labels (`<testId>.low`, `.high`). */
export function colourBar(label: string, testId: string): ColourBar {
  const bar = el('div', { className: 'colour-bar', attrs: { role: 'img', 'aria-label': label } });
  bar.style.background = `linear-gradient(to right, ${INFLUENCE_STOPS.join(', ')})`;
  const low = el('span', { testId: `${testId}.low` });
  const high = el('span', { testId: `${testId}.high` });
  const element = el('div', {}, bar, el('div', { className: 'row colour-bar-labels' }, low, high));
  return { element, low, high };
}
