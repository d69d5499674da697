/**
 * Creases panel: switches crease editing on, names what is selected, and
 * sets its sharpness with a slider (0 smooth .. 10 infinitely sharp) or the
 * Smooth and Sharp buttons; Undo and Redo step through the edits.
 */
import type { CreaseEditorState } from '../edit/crease-editor';
import { button, el, section, uniqueId } from './dom';

export interface CreasePanelHandlers {
  onEditing: (on: boolean) => void;
  onSharpness: (sharpness: number) => void;
  onUndo: () => void;
  onRedo: () => void;
}

/** The slider's top: OpenSubdiv's infinite sharpness. */
const SHARP = 10;

/** How a sharpness reads: "smooth", "2.5", "∞". */
export function sharpnessText(sharpness: number): string {
  if (sharpness <= 0) return 'smooth';
  if (sharpness >= SHARP) return '∞';
  return String(Math.round(sharpness * 100) / 100);
}

export class CreasePanel {
  readonly element: HTMLElement;
  private readonly edit: HTMLButtonElement;
  private readonly hint: HTMLElement;
  private readonly selection: HTMLOutputElement;
  private readonly slider: HTMLInputElement;
  private readonly value: HTMLOutputElement;
  private readonly smooth: HTMLButtonElement;
  private readonly sharp: HTMLButtonElement;
  private readonly undo: HTMLButtonElement;
  private readonly redo: HTMLButtonElement;
  /** The selection, slider and buttons: shown while editing. */
  private readonly controls: HTMLElement;
  private editing = false;

  constructor(handlers: CreasePanelHandlers) {
    this.edit = button(
      'Edit creases',
      'creases.edit',
      () => handlers.onEditing(!this.editing),
      'Pick control edges and vertices (M)',
    );
    this.edit.setAttribute('aria-keyshortcuts', 'm');
    this.hint = el('p', { testId: 'creases.hint', className: 'hint' });
    this.selection = el('output', { testId: 'creases.selection', attrs: { 'aria-live': 'polite' } });
    const sliderId = uniqueId('sharpness');
    this.slider = el('input', {
      testId: 'creases.sharpness',
      attrs: { type: 'range', min: '0', max: String(SHARP), step: '0.1', value: '0', id: sliderId },
    });
    this.value = el('output', { testId: 'creases.sharpness-value', attrs: { for: sliderId } });
    this.slider.addEventListener('input', () => this.showValue(Number(this.slider.value)));
    this.slider.addEventListener('change', () => handlers.onSharpness(Number(this.slider.value)));
    this.smooth = button('Smooth', 'creases.smooth', () => handlers.onSharpness(0), 'Sharpness 0 (0)');
    this.sharp = button('Sharp', 'creases.sharp', () => handlers.onSharpness(SHARP), 'Infinitely sharp (I)');
    this.undo = button('Undo', 'creases.undo', handlers.onUndo, 'Undo the last crease edit (Ctrl+Z)');
    this.redo = button('Redo', 'creases.redo', handlers.onRedo, 'Redo (Ctrl+Shift+Z)');
    this.controls = el(
      'div',
      { testId: 'creases.controls' },
      this.selection,
      el('label', { attrs: { for: sliderId }, text: 'Sharpness (0–9 keys, I: ∞)' }),
      el('div', { className: 'row' }, this.slider, this.value),
      el('div', { className: 'row wrap' }, this.smooth, this.sharp, this.undo, this.redo),
    );
    this.element = section('Creases', 'crease-panel', this.edit, this.hint, this.controls);
  }

  update(state: CreaseEditorState): void {
    this.editing = state.editing;
    this.edit.disabled = !state.available;
    this.edit.setAttribute('aria-pressed', String(state.editing));
    this.hint.textContent = !state.schemeApplies
      ? `${state.schemeLabel} ignores creases; Catmull-Clark and Loop apply them.`
      : state.editing
        ? 'Click an edge or a vertex of the control mesh; Alt+click an edge for its whole loop.'
        : 'Sharp edges and corners for Catmull-Clark and Loop.';
    const selected = state.selection;
    this.controls.hidden = !state.editing;
    this.selection.textContent = selected
      ? `${selected.label}: ${selected.mixed ? 'mixed' : sharpnessText(selected.sharpness)}`
      : 'Nothing selected';
    for (const control of [this.slider, this.smooth, this.sharp]) control.disabled = !selected;
    // The slider follows the selection, unless the user is dragging it.
    if (document.activeElement !== this.slider || !selected) this.slider.value = String(selected?.sharpness ?? 0);
    this.showValue(Number(this.slider.value));
    this.undo.disabled = !state.canUndo;
    this.redo.disabled = !state.canRedo;
  }

  private showValue(sharpness: number): void {
    this.value.textContent = sharpnessText(sharpness);
    this.slider.setAttribute('aria-valuetext', sharpnessText(sharpness));
  }
}
