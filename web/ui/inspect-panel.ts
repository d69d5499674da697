/**
 * Inspect panel: what to compute (self-intersections, enclosing sphere,
 * convex hull, minimum width: each also drawn), the Inspect button, and
 * the shown level's figures with the time each took, area, volume and box
 * diagonal beside level 0's; the first crossing pairs as buttons that
 * frame them.
 */
import type { InspectChoices, InspectorState } from '../inspect/mesh-inspector';
import { INSPECT_COLORS, type InspectLayers } from '../render/inspect-graphics';
import { button, el, section } from './dom';

export interface InspectPanelHandlers {
  onChoice: (choice: keyof InspectChoices, layer: keyof InspectLayers, on: boolean) => void;
  onInspect: () => void;
  onFrame: (pair: [number, number]) => void;
}

/** Pair buttons shown (the count says how many there are). */
const PAIR_BUTTONS = 12;

const ITEMS = [
  {
    choice: 'selfIntersections',
    layer: 'intersections',
    label: 'Self-intersections',
    color: INSPECT_COLORS.intersecting,
  },
  { choice: 'sphere', layer: 'sphere', label: 'Smallest enclosing sphere', color: INSPECT_COLORS.sphere },
  { choice: 'hull', layer: 'hull', label: 'Convex hull', color: INSPECT_COLORS.hull },
  { choice: 'width', layer: 'width', label: 'Minimum width', color: INSPECT_COLORS.planes },
] as const;

/** A figure in the panel: five significant digits, no exponent for ordinary sizes. */
export function figure(x: number): string {
  if (x === 0) return '0';
  return Math.abs(x) >= 1e-3 && Math.abs(x) < 1e6 ? String(Number(x.toPrecision(5))) : x.toPrecision(4);
}

function milliseconds(ms: number): string {
  return ms < 10 ? `${ms.toFixed(1)} ms` : `${Math.round(ms).toLocaleString('en')} ms`;
}

/** A point or direction; coordinates below 1e-12 of `scale` (rounding around 0) read 0. */
function point(p: readonly number[], scale: number): string {
  return `(${p.map((x) => figure(Math.abs(x) < 1e-12 * scale ? 0 : x)).join(', ')})`;
}

export class InspectPanel {
  readonly element: HTMLElement;
  private readonly checks = new Map<string, HTMLInputElement>();
  private readonly run: HTMLButtonElement;
  private readonly message: HTMLElement;
  private readonly results: HTMLElement;
  private readonly pairs: HTMLElement;

  constructor(private readonly handlers: InspectPanelHandlers) {
    const choices = ITEMS.map((item) => {
      const input = el('input', { testId: `inspect.choice.${item.layer}`, attrs: { type: 'checkbox' } });
      input.addEventListener('change', () => handlers.onChoice(item.choice, item.layer, input.checked));
      this.checks.set(item.choice, input);
      const swatch = el('span', { className: 'swatch', attrs: { 'aria-hidden': 'true' } });
      swatch.style.background = item.color;
      return el('label', { className: 'check' }, input, swatch, item.label);
    });
    this.run = button('Inspect', 'inspect.run', handlers.onInspect, 'Compute the chosen figures for the shown level');
    this.message = el('p', { testId: 'inspect.message', className: 'hint' });
    this.results = el('dl', { testId: 'inspect.results', className: 'inspect-results' });
    this.pairs = el('div', { testId: 'inspect.pairs', className: 'row wrap' });
    this.element = section('Inspect', 'inspect-panel', ...choices, this.run, this.message, this.results, this.pairs);
  }

  update(state: InspectorState): void {
    for (const item of ITEMS) {
      const input = this.checks.get(item.choice);
      if (input) input.checked = state.choices[item.choice];
    }
    this.run.disabled = !state.available || state.busy;
    this.run.textContent = state.busy ? 'Inspecting…' : `Inspect level ${state.level}`;
    this.message.textContent = state.message;
    this.message.hidden = state.message === '';
    const r = state.result;
    const rows: [string, string, string][] = [];
    if (r) {
      const m = r.measures;
      const c = state.control;
      const change = (now: number, before: number | undefined) =>
        state.level > 0 && before ? ` (×${figure(now / before)} of level 0)` : '';
      rows.push(['area', 'Area', `${figure(m.area)}${change(m.area, c?.area)}`]);
      rows.push([
        'volume',
        'Volume',
        m.closed ? `${figure(m.volume)}${change(m.volume, c?.closed ? c.volume : undefined)}` : 'open mesh: none',
      ]);
      rows.push(['diagonal', 'Box diagonal', `${figure(m.diagonal)}${change(m.diagonal, c?.diagonal)}`]);
      const x = r.selfIntersections;
      if (x) {
        const what =
          x.pairs === 0
            ? 'none'
            : `${x.pairs.toLocaleString('en')} pairs of faces (${x.faces.length.toLocaleString('en')} faces)`;
        rows.push(['self-intersections', 'Self-intersections', `${what} · ${milliseconds(x.ms)}`]);
      }
      if (r.sphere) {
        rows.push([
          'sphere',
          'Enclosing sphere',
          `radius ${figure(r.sphere.radius)}, centre ${point(r.sphere.center, m.diagonal)} · ${milliseconds(r.sphere.ms)}`,
        ]);
      }
      if (r.hull) {
        const h = r.hull;
        rows.push([
          'hull',
          'Convex hull',
          `${h.vertices} vertices, ${h.edges} edges, ${h.faces} triangles; area ${figure(h.area)}, volume ${figure(h.volume)} · ${milliseconds(h.ms)}`,
        ]);
      }
      if (r.width) {
        const w = r.width;
        rows.push([
          'width',
          'Minimum width',
          w.skipped
            ? 'not computed: the hull has too many vertices for the exact algorithm'
            : `${figure(w.width)}, between the planes n·x = ${figure(w.offsets[0])} and ${figure(w.offsets[1])}, n = ${point(w.normal, 1)} · ${milliseconds(w.ms)}`,
        ]);
      }
    }
    this.results.replaceChildren(
      ...rows.flatMap(([key, label, value]) => [
        el('dt', { text: label }),
        el('dd', { testId: `inspect.${key}`, text: value }),
      ]),
    );
    const listed = r?.selfIntersections?.firstPairs ?? new Uint32Array(0);
    const buttons: HTMLElement[] = [];
    for (let k = 0; k + 1 < listed.length && k < 2 * PAIR_BUTTONS; k += 2) {
      const pair: [number, number] = [listed[k], listed[k + 1]];
      const framed = state.framed?.[0] === pair[0] && state.framed?.[1] === pair[1];
      const b = button(
        `${pair[0]} × ${pair[1]}`,
        'inspect.pair',
        () => this.handlers.onFrame(pair),
        `Frame faces ${pair[0]} and ${pair[1]}`,
      );
      b.setAttribute('aria-pressed', String(framed));
      buttons.push(b);
    }
    const total = r?.selfIntersections?.pairs ?? 0;
    if (total > buttons.length && buttons.length > 0)
      buttons.push(
        el('span', { className: 'hint', text: `and ${(total - buttons.length).toLocaleString('en')} more` }),
      );
    this.pairs.replaceChildren(...buttons);
    this.pairs.hidden = buttons.length === 0;
  }
}
