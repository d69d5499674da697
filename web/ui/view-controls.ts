/**
 * The view's buttons in the Display panel: Fit, the canonical views (front,
 * top, side, iso), the saved views (save, pick, restore, delete) and the
 * line-width setting.
 */
import { CANONICAL_VIEWS, type CanonicalView } from '../render/fit';
import { DEFAULT_LINE_WIDTH, LINE_WIDTHS } from '../render/line-style';
import { button, el, uniqueId } from './dom';

export interface ViewControlsHandlers {
  onFit: () => void;
  onCanonical: (view: CanonicalView) => void;
  onSaveView: () => void;
  /** The saved view named `name`. */
  onRestoreView: (name: string) => void;
  onDeleteView: (name: string) => void;
  onLineWidth: (width: number) => void;
}

export class ViewControls {
  readonly element: HTMLElement;
  private readonly saved: HTMLSelectElement;
  private readonly restore: HTMLButtonElement;
  private readonly remove: HTMLButtonElement;
  private readonly lineWidth: HTMLSelectElement;

  constructor(handlers: ViewControlsHandlers) {
    const canonical = CANONICAL_VIEWS.map(({ name, label }) =>
      button(label, `view.${name}`, () => handlers.onCanonical(name), `Look from the ${name} and fit (V: next view)`),
    );
    this.saved = el(
      'select',
      { testId: 'view.saved', attrs: { 'aria-label': 'Saved views' } },
      el('option', { text: 'None saved', attrs: { value: '' } }),
    );
    this.restore = button(
      'Restore',
      'view.restore',
      () => handlers.onRestoreView(this.saved.value),
      'Go back to the saved viewpoint',
    );
    this.remove = button(
      'Delete',
      'view.delete',
      () => handlers.onDeleteView(this.saved.value),
      'Forget the saved viewpoint',
    );
    const widthId = uniqueId('line-width');
    this.lineWidth = el('select', { testId: 'controls.line-width', attrs: { id: widthId } });
    for (const w of LINE_WIDTHS) this.lineWidth.append(el('option', { text: `${w} px`, attrs: { value: String(w) } }));
    this.lineWidth.value = String(DEFAULT_LINE_WIDTH);
    this.lineWidth.addEventListener('change', () => handlers.onLineWidth(Number(this.lineWidth.value)));
    this.element = el(
      'div',
      { className: 'view-controls' },
      el(
        'div',
        { className: 'row wrap' },
        button(
          'Fit view',
          'view.fit',
          handlers.onFit,
          'Show the whole model, the control mesh and markers included (F)',
        ),
        button('Save view', 'view.save', handlers.onSaveView, 'Remember this viewpoint, also for other models'),
      ),
      el('div', { className: 'row wrap', attrs: { role: 'group', 'aria-label': 'Canonical views' } }, ...canonical),
      el('div', { className: 'row wrap' }, this.saved, this.restore, this.remove),
      el('div', { className: 'row' }, el('label', { attrs: { for: widthId }, text: 'Line width' }), this.lineWidth),
    );
  }

  /** Shows the saved views' names, `selected` chosen, and the line width. */
  update(names: readonly string[], selected: string | null, lineWidth: number): void {
    const current = [...this.saved.options].map((o) => o.value).filter((v) => v !== '');
    if (current.length !== names.length || current.some((n, i) => n !== names[i])) {
      const options = names.map((name) => el('option', { text: name, attrs: { value: name } }));
      this.saved.replaceChildren(
        ...(options.length > 0 ? options : [el('option', { text: 'None saved', attrs: { value: '' } })]),
      );
    }
    if (selected !== null) this.saved.value = selected;
    const none = names.length === 0;
    this.saved.disabled = none;
    this.restore.disabled = none;
    this.remove.disabled = none;
    const width = String(lineWidth);
    // A width from a link that the menu lacks gets its own entry.
    if (![...this.lineWidth.options].some((o) => o.value === width)) {
      this.lineWidth.append(el('option', { text: `${width} px`, attrs: { value: width } }));
    }
    this.lineWidth.value = width;
  }
}
