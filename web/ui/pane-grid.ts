/**
 * The view area as side-by-side panes: the app's own view first, the other
 * panes beside it (two, three in a row, four as two by two; stacked on a
 * narrow screen), each with a header that names its scheme (a menu in the
 * other panes), its level and counts, steps its level when levels go
 * apart, and says why a level is missing.
 */
import type { SchemeName } from '../core/mesh';
import type { PaneState, SideBySideState } from '../teach/side-by-side';
import { PANE_SCHEMES, schemeInfo } from '../viewer/scheme-info';
import { button, el } from './dom';
import { faceTypes } from './facts-panel';

export interface PaneGridHandlers {
  onScheme: (index: number, scheme: SchemeName) => void;
  onStep: (index: number, delta: number) => void;
  /** A key pressed in pane `index`'s view (rotate, pan, zoom). */
  onKey: (index: number, event: KeyboardEvent) => void;
}

interface PaneHeader {
  element: HTMLElement;
  scheme: HTMLSelectElement | HTMLElement;
  level: HTMLElement;
  down: HTMLButtonElement;
  up: HTMLButtonElement;
  message: HTMLElement;
}

export class PaneGrid {
  readonly element: HTMLElement;
  private readonly panes: HTMLElement[] = [];
  private readonly headers: PaneHeader[] = [];

  /** `first` is the app's own view (pane 0), kept as it is. */
  constructor(
    first: HTMLElement,
    private readonly handlers: PaneGridHandlers,
  ) {
    this.element = el('div', { testId: 'panes', className: 'pane-grid', attrs: { 'data-count': '1' } }, first);
    this.panes.push(first);
    this.headers.push(this.header(0));
    first.append(this.headers[0].element);
  }

  /** A new pane at `index` (1 or more): the element its viewer draws in. */
  add(index: number): HTMLElement {
    const view = el('div', {
      testId: `pane.${index}.view`,
      className: 'pane-view',
      attrs: {
        role: 'region',
        tabindex: '0',
        'aria-label': `Pane ${index + 1}: drag or arrow keys rotate, right-drag or Shift+arrows pan, wheel or +/− zoom`,
      },
    });
    view.addEventListener('keydown', (event) => this.handlers.onKey(index, event));
    const header = this.header(index);
    const pane = el('div', { testId: `pane.${index}`, className: 'pane' }, view, header.element);
    this.panes[index] = pane;
    this.headers[index] = header;
    this.element.append(pane);
    this.element.dataset.count = String(this.panes.length);
    return view;
  }

  remove(index: number): void {
    this.panes[index]?.remove();
    this.panes.length = index;
    this.headers.length = index;
    this.element.dataset.count = String(this.panes.length);
  }

  update(state: SideBySideState): void {
    this.headers[0].element.hidden = state.count < 2;
    state.panes.forEach((pane, i) => {
      const header = this.headers[i];
      if (header) this.fill(header, pane, i, state.together);
    });
  }

  private fill(header: PaneHeader, pane: PaneState, index: number, together: boolean): void {
    const v = pane.viewer;
    if (header.scheme instanceof HTMLSelectElement) header.scheme.value = pane.scheme;
    else header.scheme.textContent = schemeInfo(pane.scheme).label;
    const counts = v.facts ? ` · ${v.facts.vertices.toLocaleString('en')} vertices · ${faceTypes(v.facts)}` : '';
    const triangulated = pane.triangulated ? ' · triangulated first' : '';
    const tags = pane.ignoresTags ? ' · creases not applied' : '';
    const busy = v.busy ? ' · working…' : '';
    header.level.textContent = v.levelCount > 0 ? `level ${v.level}${counts}${triangulated}${tags}${busy}` : busy;
    const apart = !together && index > 0;
    header.down.hidden = !apart;
    header.up.hidden = !apart;
    header.down.disabled = v.busy !== null || v.level === 0;
    header.up.disabled = v.busy !== null || v.levelCount === 0;
    header.message.textContent = pane.message;
    header.message.hidden = header.message.textContent === '';
  }

  private header(index: number): PaneHeader {
    let scheme: HTMLSelectElement | HTMLElement;
    if (index === 0) {
      scheme = el('span', { testId: 'pane.0.scheme', className: 'pane-scheme' });
    } else {
      const select = el('select', {
        testId: `pane.${index}.scheme`,
        attrs: { 'aria-label': `Scheme of pane ${index + 1}` },
      });
      for (const name of PANE_SCHEMES)
        select.append(el('option', { text: schemeInfo(name).label, attrs: { value: name } }));
      select.addEventListener('change', () => this.handlers.onScheme(index, select.value as SchemeName));
      scheme = select;
    }
    const level = el('span', { testId: `pane.${index}.level` });
    const down = button(
      '−',
      `pane.${index}.down`,
      () => this.handlers.onStep(index, -1),
      'Previous level of this pane',
    );
    const up = button('+', `pane.${index}.up`, () => this.handlers.onStep(index, 1), 'Next level of this pane');
    const message = el('span', { testId: `pane.${index}.message`, className: 'pane-message' });
    const element = el(
      'div',
      { testId: `pane.${index}.header`, className: 'pane-header' },
      el('span', { className: 'pane-number', text: String(index + 1) }),
      scheme,
      level,
      down,
      up,
      message,
    );
    return { element, scheme, level, down, up, message };
  }
}
