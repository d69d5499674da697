/** A modal question inside the page (never window.confirm): resolves true for OK, false otherwise. */
import { button, el } from './dom';

export class ConfirmDialog {
  readonly element: HTMLDialogElement;
  private readonly title: HTMLElement;
  private readonly message: HTMLElement;
  private readonly ok: HTMLButtonElement;
  private resolve: ((answer: boolean) => void) | null = null;

  constructor() {
    this.title = el('h2', { attrs: { id: 'confirm-title' } });
    this.message = el('p', { testId: 'confirm.message', attrs: { id: 'confirm-message' } });
    this.ok = button('OK', 'confirm.ok', () => this.answer(true));
    this.element = el(
      'dialog',
      {
        testId: 'confirm.dialog',
        className: 'confirm-dialog',
        attrs: { 'aria-labelledby': 'confirm-title', 'aria-describedby': 'confirm-message' },
      },
      this.title,
      this.message,
      el(
        'div',
        { className: 'dialog-buttons' },
        button('Cancel', 'confirm.cancel', () => this.answer(false)),
        this.ok,
      ),
    );
    // Escape closes the dialog: that is a "no".
    this.element.addEventListener('close', () => {
      if (!this.element.open) this.answer(false);
    });
  }

  ask(title: string, message: string, okLabel: string): Promise<boolean> {
    this.answer(false);
    this.title.textContent = title;
    this.message.textContent = message;
    this.ok.textContent = okLabel;
    this.element.showModal();
    return new Promise((resolve) => {
      this.resolve = resolve;
    });
  }

  get open(): boolean {
    return this.element.open;
  }

  private answer(yes: boolean): void {
    const resolve = this.resolve;
    this.resolve = null;
    if (this.element.open) this.element.close();
    resolve?.(yes);
  }
}
