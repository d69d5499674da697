/**
 * The element's control bar: `minimal` has the level stepper and the scheme
 * menu; `full` adds the render mode, the control-mesh and control-edge
 * overlays, Fit and the counts. With tool="split" (either mode) a slider
 * and Play run the step from the split to the smoothed level. Every control
 * is a native element with a `part` name, so a page styles it with
 * `subdiv-viewer::part(level-up)`.
 */
import type { SchemeName } from '../core/mesh';
import { RENDER_MODES, type RenderMode } from '../render/render-mode';
import type { SplitState } from '../teach/split-smooth';
import { el, uniqueId } from '../ui/dom';
import { faceTypes } from '../ui/facts-panel';
import { SCHEME_NAMES, schemeInfo } from '../viewer/scheme-info';
import type { ViewerState } from '../viewer/subdiv-viewer';
import { type ControlsMode, MAX_PARAM_LEVELS } from '../viewer/viewer-params';

export interface EmbedControlHandlers {
  stepLevel: (delta: number) => void;
  scheme: (scheme: SchemeName) => void;
  renderMode: (mode: RenderMode) => void;
  overlay: (name: 'control' | 'curves', on: boolean) => void;
  fit: () => void;
  /** The split slider moved (0: the split alone … 1: smoothed). */
  split: (t: number) => void;
  /** Play the step from the split to the smoothed level. */
  play: () => void;
}

function withPart<T extends HTMLElement>(element: T, part: string, label?: string): T {
  element.setAttribute('part', part);
  if (label) element.setAttribute('aria-label', label);
  return element;
}

export class EmbedControls {
  readonly element: HTMLElement;
  private readonly down: HTMLButtonElement;
  private readonly up: HTMLButtonElement;
  private readonly level: HTMLOutputElement;
  private readonly scheme: HTMLSelectElement;
  private readonly mode: HTMLSelectElement;
  private readonly control: HTMLInputElement;
  private readonly curves: HTMLInputElement;
  private readonly facts: HTMLElement;
  private readonly fullOnly: HTMLElement[];
  /** Split, then smooth: the slider and Play, shown with tool="split". */
  private readonly splitGroup: HTMLElement;
  private readonly splitSlider: HTMLInputElement;
  private readonly play: HTMLButtonElement;

  constructor(handlers: EmbedControlHandlers) {
    this.down = withPart(el('button', { text: '−', attrs: { type: 'button' } }), 'level-down', 'Previous level');
    this.up = withPart(el('button', { text: '+', attrs: { type: 'button' } }), 'level-up', 'Next level (subdivide)');
    this.down.addEventListener('click', () => handlers.stepLevel(-1));
    this.up.addEventListener('click', () => handlers.stepLevel(1));
    this.level = withPart(el('output', { className: 'level', text: '–' }), 'level');
    this.scheme = withPart(el('select'), 'scheme', 'Subdivision scheme');
    for (const name of SCHEME_NAMES) {
      if (name !== 'custom') this.scheme.append(el('option', { text: schemeInfo(name).label, attrs: { value: name } }));
    }
    this.scheme.addEventListener('change', () => handlers.scheme(this.scheme.value as SchemeName));
    this.mode = withPart(el('select'), 'render-mode', 'Render mode');
    for (const { mode, label } of RENDER_MODES) this.mode.append(el('option', { text: label, attrs: { value: mode } }));
    this.mode.addEventListener('change', () => handlers.renderMode(this.mode.value as RenderMode));
    this.control = el('input', { attrs: { type: 'checkbox' } });
    this.control.addEventListener('change', () => handlers.overlay('control', this.control.checked));
    this.curves = el('input', { attrs: { type: 'checkbox' } });
    this.curves.addEventListener('change', () => handlers.overlay('curves', this.curves.checked));
    const fit = withPart(el('button', { text: 'Fit', attrs: { type: 'button' } }), 'fit', 'Fit the view');
    fit.addEventListener('click', handlers.fit);
    this.facts = withPart(el('span', { className: 'facts' }), 'facts');
    this.fullOnly = [
      this.mode,
      withPart(el('label', { attrs: { title: 'Control mesh' } }, this.control, 'Control mesh'), 'control-mesh'),
      withPart(el('label', { attrs: { title: 'Control edges' } }, this.curves, 'Control edges'), 'control-edges'),
      fit,
      this.facts,
    ];
    this.element = withPart(
      el('div', { className: 'bar', attrs: { role: 'toolbar', 'aria-label': 'Viewer controls' } }),
      'controls',
    );
    const sliderId = uniqueId('split');
    this.splitSlider = withPart(
      el('input', { attrs: { id: sliderId, type: 'range', min: '0', max: '1', step: '0.01', value: '1' } }),
      'split',
      'Split (0) to smoothed (1)',
    );
    this.splitSlider.addEventListener('input', () => handlers.split(Number(this.splitSlider.value)));
    this.play = withPart(el('button', { text: 'Play', attrs: { type: 'button' } }), 'play', 'Play the step');
    this.play.addEventListener('click', handlers.play);
    this.splitGroup = el('span', { className: 'split' }, this.splitSlider, this.play);
    this.splitGroup.hidden = true;
    this.element.append(this.down, this.level, this.up, this.scheme, this.splitGroup, ...this.fullOnly);
  }

  /** The split slider and Play for `state` (null: tool is not split, they are hidden). */
  updateSplit(state: SplitState | null): void {
    this.splitGroup.hidden = state === null;
    if (!state) return;
    this.splitSlider.disabled = !state.available;
    this.play.disabled = !state.available || state.animating;
    // Not under the pointer of someone dragging it (the drawing follows a moment later).
    const root = this.splitSlider.getRootNode() as Document | ShadowRoot;
    if (root.activeElement !== this.splitSlider || state.animating) this.splitSlider.value = String(state.t);
  }

  setMode(mode: ControlsMode): void {
    this.element.hidden = mode === 'none';
    for (const e of this.fullOnly) e.hidden = mode !== 'full';
  }

  update(state: ViewerState): void {
    const loaded = state.levelCount > 0;
    const busy = state.busy !== null;
    // Going down stays possible during a step (it stops the step); up waits, and ends at the last level a page may ask.
    this.down.disabled = !loaded || state.level === 0;
    this.up.disabled = !loaded || busy || state.level >= MAX_PARAM_LEVELS;
    this.level.textContent = loaded ? `Level ${state.level}` : '–';
    if (this.scheme.value !== state.scheme) {
      if (![...this.scheme.options].some((o) => o.value === state.scheme)) {
        this.scheme.append(el('option', { text: schemeInfo(state.scheme).label, attrs: { value: state.scheme } }));
      }
      this.scheme.value = state.scheme;
    }
    this.mode.value = state.renderMode;
    this.control.checked = state.overlays.control;
    this.curves.checked = state.overlays.curves;
    const f = state.facts;
    this.facts.textContent = f ? `${f.vertices} V · ${f.edges} E · ${f.faces} F (${faceTypes(f)})` : '';
  }
}
