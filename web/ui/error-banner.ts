/**
 * The one place errors are shown: a visible role="alert" banner naming the
 * file (or URL) and the problem, with an optional action (e.g. "Triangulate
 * and subdivide") and a Dismiss button.
 */
import { button, el } from './dom';

export interface ErrorAction {
  label: string;
  run: () => void;
}

export class ErrorBanner {
  readonly element: HTMLElement;
  private readonly source: HTMLElement;
  private readonly message: HTMLElement;
  private readonly actions: HTMLElement;

  constructor() {
    this.source = el('strong', { testId: 'error.source' });
    this.message = el('span', { testId: 'error.message' });
    this.actions = el('span', { className: 'error-actions' });
    this.element = el(
      'div',
      { testId: 'error.banner', className: 'error-banner', attrs: { role: 'alert' } },
      el('p', {}, this.source, this.message),
      this.actions,
    );
    this.element.hidden = true;
  }

  /** Shows `message` about `source`; both are inserted as text. */
  show(source: string, message: string, action?: ErrorAction): void {
    this.source.textContent = source ? `${source}: ` : '';
    this.message.textContent = message;
    this.actions.replaceChildren();
    if (action) {
      this.actions.append(
        button(action.label, 'error.action', () => {
          this.hide();
          action.run();
        }),
      );
    }
    this.actions.append(button('Dismiss', 'error.dismiss', () => this.hide()));
    this.element.hidden = false;
  }

  hide(): void {
    this.element.hidden = true;
  }
}
