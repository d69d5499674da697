/**
 * A non-blocking notice above the view (role="status"): e.g. the values of
 * a link that were ignored while the rest of it was applied.
 */
import { button, el } from './dom';

export class NoticeBar {
  readonly element: HTMLElement;
  private readonly message: HTMLElement;

  constructor() {
    this.message = el('span', { testId: 'notice.message' });
    this.element = el(
      'div',
      { testId: 'notice', className: 'notice-bar', attrs: { role: 'status' } },
      el('p', {}, this.message),
      button('Dismiss', 'notice.dismiss', () => this.hide()),
    );
    this.element.hidden = true;
  }

  /** Shows `text` (as text); an empty string hides the notice. */
  show(text: string): void {
    this.message.textContent = text;
    this.element.hidden = text === '';
  }

  hide(): void {
    this.element.hidden = true;
  }

  /** The text shown, or null when hidden. */
  get text(): string | null {
    return this.element.hidden ? null : this.message.textContent;
  }
}
