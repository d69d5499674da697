/**
 * The colour bar of a basis function's influence (viridis, as the surface
 * is coloured: render/level-graphics.ts), for the app's basis panel and the
 * `<subdiv-viewer>` caption.
 */
import { INFLUENCE_STOPS } from '../render/level-graphics';
import { el } from './dom';

/** A bar from no influence (dark purple, left) to the largest (yellow, right), described for screen readers. */
export function influenceBar(className = 'colour-bar'): HTMLElement {
  const bar = el('div', {
    className,
    attrs: { role: 'img', 'aria-label': 'colour bar: no influence (dark) to the largest (yellow)' },
  });
  bar.style.background = `linear-gradient(to right, ${INFLUENCE_STOPS.join(', ')})`;
  return bar;
}

/** The values at the bar's ends, as written under it: 0 (or a negative least value) and the largest. */
export function influenceEnds(min: number, max: number): [string, string] {
  return [min < 0 ? min.toFixed(4) : '0', max.toFixed(4)];
}
