/**
 * The header's Share and Embed… buttons, a live region that says what Share
 * did ("Link copied", or why there is no link), and a read-only field with
 * the link when the clipboard refused it, selected so Ctrl+C copies it.
 */
import { button, el } from './dom';

export interface SharePanelHandlers {
  onShare: () => void;
  onEmbed: () => void;
}

/** How long "Link copied" stays, in milliseconds; refusals stay until the next action. */
const CONFIRMATION_MS = 6000;

export class SharePanel {
  readonly element: HTMLElement;
  readonly embedButton: HTMLButtonElement;
  private readonly status: HTMLElement;
  private readonly linkField: HTMLInputElement;
  private readonly linkBox: HTMLElement;
  private timer: ReturnType<typeof setTimeout> | undefined;

  constructor(handlers: SharePanelHandlers) {
    this.status = el('span', {
      testId: 'share.status',
      className: 'share-status',
      attrs: { role: 'status', 'aria-live': 'polite' },
    });
    this.linkField = el('input', {
      testId: 'share.link',
      attrs: { type: 'text', readonly: '', 'aria-label': 'Link to this view', spellcheck: 'false' },
    });
    this.linkField.addEventListener('focus', () => this.linkField.select());
    this.linkBox = el(
      'div',
      { className: 'share-link', testId: 'share.link-box' },
      this.linkField,
      button('Close', 'share.link-close', () => this.clear()),
    );
    this.linkBox.hidden = true;
    this.embedButton = button(
      'Embed…',
      'embed.button',
      handlers.onEmbed,
      'HTML to show this view in a teaching page (an element or an iframe)',
    );
    this.element = el(
      'div',
      { className: 'share-panel' },
      button(
        'Share',
        'share.button',
        handlers.onShare,
        'Copy a link to this view: model, scheme, level, display, camera',
      ),
      this.embedButton,
      this.status,
      this.linkBox,
    );
  }

  /** Says `message` in the live region; a confirmation goes away by itself, a refusal stays. */
  say(message: string, confirmation = false): void {
    clearTimeout(this.timer);
    this.linkBox.hidden = true;
    this.status.textContent = message;
    if (confirmation) this.timer = setTimeout(() => this.clear(), CONFIRMATION_MS);
  }

  /** Shows `link` in a selected field (the clipboard refused it) with `message`. */
  showLink(link: string, message: string): void {
    this.say(message);
    this.linkField.value = link;
    this.linkBox.hidden = false;
    this.linkField.focus();
    this.linkField.select();
  }

  clear(): void {
    clearTimeout(this.timer);
    this.status.textContent = '';
    this.linkBox.hidden = true;
  }
}
