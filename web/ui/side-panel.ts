/**
 * Side-by-side panel: how many panes, levels together or apart, which two
 * panes are measured, the colours by distance, and the measured symmetric
 * Hausdorff distance with its share of the diagonal and its colour bar.
 */
import { distanceText, hausdorffText, type SideBySideState } from '../teach/side-by-side';
import { schemeInfo } from '../viewer/scheme-info';
import { MAX_PANES } from '../viewer/viewer-params';
import { el, section, uniqueId } from './dom';
import { type LabelledBar, labelledInfluenceBar } from './influence-bar';

export interface SidePanelHandlers {
  onCount: (count: number) => void;
  onTogether: (together: boolean) => void;
  onPair: (a: number, b: number) => void;
  onColours: (on: boolean) => void;
}

export class SidePanel {
  readonly element: HTMLElement;
  private readonly count: HTMLSelectElement;
  private readonly options: HTMLElement;
  private readonly together: HTMLInputElement;
  private readonly colours: HTMLInputElement;
  private readonly pairRow: HTMLElement;
  private readonly pair: [HTMLSelectElement, HTMLSelectElement];
  private readonly result: HTMLElement;
  private readonly legend: HTMLElement;
  private readonly bar: LabelledBar;

  constructor(handlers: SidePanelHandlers) {
    const countId = uniqueId('panes');
    this.count = el('select', { testId: 'side.count', attrs: { id: countId } });
    for (let n = 1; n <= MAX_PANES; ++n)
      this.count.append(el('option', { text: n === 1 ? 'one view' : `${n} panes`, attrs: { value: String(n) } }));
    this.count.addEventListener('change', () => handlers.onCount(Number(this.count.value)));
    this.together = el('input', { testId: 'side.together', attrs: { type: 'checkbox' } });
    this.together.addEventListener('change', () => handlers.onTogether(this.together.checked));
    this.colours = el('input', { testId: 'side.colours', attrs: { type: 'checkbox' } });
    this.colours.addEventListener('change', () => handlers.onColours(this.colours.checked));
    const pairSelect = (testId: string, label: string) => el('select', { testId, attrs: { 'aria-label': label } });
    this.pair = [pairSelect('side.pair-a', 'First pane measured'), pairSelect('side.pair-b', 'Second pane measured')];
    for (const select of this.pair)
      select.addEventListener('change', () => handlers.onPair(Number(this.pair[0].value), Number(this.pair[1].value)));
    this.pairRow = el(
      'div',
      { className: 'row' },
      el('span', { text: 'Distance of' }),
      this.pair[0],
      el('span', { text: 'and' }),
      this.pair[1],
    );
    this.result = el('p', { testId: 'side.distance', attrs: { 'aria-live': 'polite' } });
    this.bar = labelledInfluenceBar(
      'side',
      'colour bar: on the other surface (dark) to the Hausdorff distance (yellow)',
    );
    this.legend = el('div', { testId: 'side.legend' }, this.bar.element);
    this.options = el(
      'div',
      {},
      el('label', { className: 'check' }, this.together, 'Step levels together'),
      this.pairRow,
      el('label', { className: 'check' }, this.colours, 'Colour by distance to the other surface'),
      this.result,
      this.legend,
    );
    this.element = section(
      'Side by side',
      'side-panel',
      el('div', { className: 'row' }, el('label', { attrs: { for: countId }, text: 'Panes' }), this.count),
      this.options,
    );
  }

  update(state: SideBySideState, available: boolean): void {
    this.count.value = String(state.count);
    this.count.disabled = !available;
    this.options.hidden = state.count < 2;
    this.together.checked = state.together;
    this.colours.checked = state.colours;
    this.pairRow.hidden = state.count < 3;
    state.pair.forEach((chosen, i) => {
      const select = this.pair[i];
      if (select.options.length !== state.count)
        select.replaceChildren(
          ...Array.from({ length: state.count }, (_, k) =>
            el('option', { text: `pane ${k + 1}`, attrs: { value: String(k) } }),
          ),
        );
      select.value = String(chosen);
    });
    const d = state.distance;
    this.legend.hidden = !d || !state.colours;
    if (state.message) {
      this.result.textContent = state.message;
    } else if (d) {
      const [a, b] = d.panes.map((p) => state.panes[p]);
      const names = [a, b].map((p, i) => `${schemeInfo(p?.scheme ?? '').label} level ${d.levels[i]}`);
      const figure =
        d.distance <= d.errorBound
          ? `${hausdorffText(d)}: the surfaces agree`
          : `${distanceText(d.distance)}, ${(100 * d.relative).toPrecision(3)} % of the diagonal ` +
            `(${distanceText(d.diagonal)}; within ${distanceText(d.errorBound)})`;
      this.result.textContent =
        `Hausdorff distance between ${names[0]} and ${names[1]}: ${figure}.` +
        (state.measuring ? ' Measuring again…' : '');
      this.bar.low.textContent = '0';
      this.bar.high.textContent = distanceText(d.distance);
    } else {
      this.result.textContent = state.measuring ? 'Measuring the distance…' : '';
    }
  }
}
