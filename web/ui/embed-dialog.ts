/**
 * The Embed dialog: a modal <dialog> (Esc closes it, focus returns to the
 * button that opened it) with HTML snippets to paste into a teaching page,
 * each in a read-only text area with a Copy button, and notes on what the
 * snippets cannot carry. When there is nothing that can be embedded it says why instead.
 */
import { button, el, uniqueId } from './dom';

/** One snippet the dialog offers. */
export interface EmbedSnippet {
  /** Used in test ids (`embed.element.code`). */
  id: string;
  title: string;
  /** One line: when to use it. */
  hint: string;
  code: string;
}

/** What the dialog shows: snippets and notes, or the reason there are none. */
export type EmbedContent = { snippets: EmbedSnippet[]; notes: string[] } | { refusal: string };

export class EmbedDialog {
  readonly element: HTMLDialogElement;
  private readonly body: HTMLElement;
  private readonly closeButton: HTMLButtonElement;
  private opener: HTMLElement | null = null;

  constructor() {
    const titleId = uniqueId('embed-title');
    this.body = el('div', { className: 'embed-body' });
    this.closeButton = button('Close', 'embed.close', () => this.element.close());
    this.element = el(
      'dialog',
      { testId: 'embed.dialog', className: 'embed-dialog', attrs: { 'aria-labelledby': titleId } },
      el('h2', { className: 'embed-title', text: 'Embed this view in a page', attrs: { id: titleId } }),
      this.body,
      el('div', { className: 'dialog-buttons' }, this.closeButton),
    );
    // Esc (the dialog's cancel) and Close both end here: focus goes back to where it was.
    this.element.addEventListener('close', () => {
      this.opener?.focus();
      this.opener = null;
    });
  }

  get open(): boolean {
    return this.element.open;
  }

  /** Opens the dialog with `content`; `opener` gets the focus back when it closes. */
  show(content: EmbedContent, opener: HTMLElement | null): void {
    this.opener = opener;
    if ('refusal' in content) {
      this.body.replaceChildren(
        el('p', { testId: 'embed.refusal', className: 'embed-refusal', text: content.refusal }),
      );
    } else {
      this.body.replaceChildren(
        el('p', {
          className: 'hint',
          text: 'Paste one of these into the HTML of a web page. Each shows this model, scheme, level, display and camera; readers can turn the model and step through the levels.',
        }),
        ...content.snippets.map((snippet) => this.snippetBlock(snippet)),
        ...content.notes.map((note) => el('p', { testId: 'embed.note', className: 'embed-note', text: note })),
      );
    }
    if (!this.element.open) this.element.showModal();
    // Start on the first Copy button (or Close): the snippets are long, the action is what the reader wants.
    (this.body.querySelector<HTMLButtonElement>('button') ?? this.closeButton).focus();
  }

  private snippetBlock(snippet: EmbedSnippet): HTMLElement {
    const codeId = uniqueId(`embed-${snippet.id}`);
    const code = el('textarea', {
      testId: `embed.${snippet.id}.code`,
      className: 'embed-code',
      attrs: { id: codeId, readonly: '', spellcheck: 'false', wrap: 'soft' },
    });
    code.value = snippet.code;
    // Rows for the whole snippet at about 90 characters a line (CSS field-sizing does better where supported).
    code.rows = Math.min(
      12,
      snippet.code.split('\n').reduce((n, line) => n + Math.ceil(line.length / 90), 0),
    );
    const status = el('span', {
      testId: `embed.${snippet.id}.status`,
      className: 'embed-status',
      attrs: { role: 'status', 'aria-live': 'polite' },
    });
    const copy = button('Copy', `embed.${snippet.id}.copy`, () => {
      navigator.clipboard.writeText(snippet.code).then(
        () => {
          status.textContent = 'Copied';
        },
        () => {
          code.focus();
          code.select();
          status.textContent = 'Copying was refused: the snippet is selected, press Ctrl+C.';
        },
      );
    });
    copy.setAttribute('aria-describedby', codeId);
    return el(
      'section',
      { className: 'embed-snippet', testId: `embed.${snippet.id}` },
      el(
        'div',
        { className: 'embed-snippet-head' },
        el(
          'label',
          { className: 'embed-label', attrs: { for: codeId } },
          el('strong', { text: snippet.title }),
          ` — ${snippet.hint}`,
        ),
        copy,
        status,
      ),
      code,
    );
  }
}
