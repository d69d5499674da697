/**
 * The caption of a `<subdiv-viewer>`'s teaching tool (part `tool`), a row
 * between the picture and the control bar, so that it never covers the
 * model: one line saying what the tool shows, a second for a stencil's
 * formula, and for a basis function its colour bar with the values at its
 * ends. A polite live region: a screen reader hears each new stencil.
 */
import { el } from '../ui/dom';
import { influenceBar } from '../ui/influence-bar';

/** What the caption shows. */
export interface CaptionContent {
  /** The main line. */
  line: string;
  /** A second, quieter line (a stencil's formula), cut to the width with its whole text as a tooltip. */
  note?: string;
  /** A colour bar with these values at its ends (a basis function). */
  legend?: [string, string];
  /** The line is a hint or a problem, not a result. */
  hint?: boolean;
}

export class EmbedCaption {
  readonly element: HTMLElement;
  private readonly line: HTMLElement;
  private readonly note: HTMLElement;
  private readonly legend: HTMLElement;
  private readonly low: HTMLElement;
  private readonly high: HTMLElement;

  /** `part`: the caption's part name (`tool`, `distance`); `barLabel` describes its colour bar. */
  constructor(part = 'tool', barLabel?: string) {
    this.line = el('p', { className: 'tool-line' });
    this.note = el('p', { className: 'tool-note' });
    this.low = el('span');
    this.high = el('span');
    this.legend = el('div', { className: 'tool-legend' }, this.low, influenceBar('tool-bar', barLabel), this.high);
    this.element = el(
      'div',
      { className: 'tool', attrs: { part, 'aria-live': 'polite' } },
      this.line,
      this.legend,
      this.note,
    );
    this.element.hidden = true;
  }

  /** Shows `content`, or hides the caption (null). */
  show(content: CaptionContent | null): void {
    this.element.hidden = content === null;
    if (!content) return;
    // Only what changed: the caption is a live region, and a screen reader reads each change.
    if (this.line.textContent !== content.line) this.line.textContent = content.line;
    this.line.classList.toggle('hint', content.hint === true);
    if (this.note.textContent !== (content.note ?? '')) {
      this.note.textContent = content.note ?? '';
      this.note.title = content.note ?? '';
    }
    this.note.hidden = !content.note;
    this.legend.hidden = !content.legend;
    // Hidden parts keep no text: the caption's text is what it shows.
    [this.low.textContent, this.high.textContent] = content.legend ?? ['', ''];
  }
}
