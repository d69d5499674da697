/**
 * A colour bar over a view's canvas (its bottom left corner): a title, the
 * gradient and the values at its ends and middle, and a line on what the
 * colours leave out. Styled inline, as the view's labels are, so it looks
 * the same in the app, in a `<subdiv-viewer>`'s shadow root and in
 * embed.html. (ui/influence-bar.ts draws the tools' viridis bars in the
 * panels; the viewer, below the panels, cannot use it.)
 */

export interface LegendContent {
  title: string;
  /** CSS colours from the left end to the right. */
  stops: readonly string[];
  low: string;
  middle: string;
  high: string;
  /** A line under the bar (what is clamped, what is not coloured). */
  note: string;
}

function span(testId: string, css = ''): HTMLSpanElement {
  const element = document.createElement('span');
  element.dataset.testid = testId;
  if (css) element.style.cssText = css;
  return element;
}

export class ColourLegend {
  readonly element: HTMLDivElement;
  private readonly title = span('view.colour-bar.title', 'display:block;font-weight:600;margin-bottom:3px');
  private readonly bar = span('view.colour-bar.gradient', 'display:block;height:12px;border-radius:2px');
  private readonly low = span('view.colour-bar.low');
  private readonly middle = span('view.colour-bar.middle');
  private readonly high = span('view.colour-bar.high');
  private readonly note = span('view.colour-bar.note', 'display:block;margin-top:3px;color:#4b5563');

  constructor(container: HTMLElement) {
    this.element = document.createElement('div');
    this.element.dataset.testid = 'view.colour-bar';
    this.element.setAttribute('role', 'img');
    // Fit keeps the model out from under it (fit.ts freeRect).
    this.element.setAttribute('data-covers-view', '');
    this.element.style.cssText =
      'position:absolute;left:10px;bottom:10px;width:min(270px, calc(100% - 40px));box-sizing:border-box;padding:6px 8px;border-radius:4px;' +
      'font:11px/1.3 system-ui,sans-serif;color:#1f2937;background:rgba(255,255,255,0.9);' +
      'border:1px solid #d1d5db;pointer-events:none;display:none';
    const ends = document.createElement('div');
    ends.style.cssText = 'display:flex;justify-content:space-between;margin-top:2px;font-variant-numeric:tabular-nums';
    ends.append(this.low, this.middle, this.high);
    this.element.append(this.title, this.bar, ends, this.note);
    // The view's container is its positioning context (the canvas fills it).
    if (getComputedStyle(container).position === 'static') container.style.position = 'relative';
    container.append(this.element);
  }

  show(content: LegendContent): void {
    this.title.textContent = content.title;
    this.bar.style.background = `linear-gradient(to right, ${content.stops.join(', ')})`;
    this.low.textContent = content.low;
    this.middle.textContent = content.middle;
    this.high.textContent = content.high;
    this.note.textContent = content.note;
    this.element.setAttribute(
      'aria-label',
      `${content.title}: colours from ${content.low} to ${content.high}. ${content.note}`,
    );
    this.element.style.display = 'block';
  }

  hide(): void {
    this.element.style.display = 'none';
  }

  get shown(): boolean {
    return this.element.style.display !== 'none';
  }

  dispose(): void {
    this.element.remove();
  }
}
