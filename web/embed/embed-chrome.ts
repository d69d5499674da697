/**
 * What `<subdiv-viewer>` shows around the picture, in its shadow root: the
 * stage the viewer draws into, a placeholder before the model, the message
 * of the last failure, the busy box with Cancel, a live region for screen
 * readers, the panes beside it (side by side), and below them the teaching
 * tool's and the distance's captions and the control bar.
 */
import { el } from '../ui/dom';
import type { EmbedCaption } from './embed-caption';
import type { EmbedControls } from './embed-controls';
import { EMBED_CSS } from './embed-styles';

export class EmbedChrome {
  /** The viewer's container. */
  readonly stage: HTMLElement;
  /** The stage and, side by side, the panes beside it (part `panes`). */
  private readonly panes: HTMLElement;
  /** Each pane's label (scheme and level), the stage's first. */
  private readonly labels: HTMLElement[] = [];
  private readonly placeholder: HTMLElement;
  private readonly message: HTMLElement;
  private readonly status: HTMLElement;
  private readonly busyBox: HTMLElement;
  private readonly busyLabel: HTMLElement;

  /** `captions`: the rows between the picture and the controls (the tool's, the distance's). */
  constructor(root: ShadowRoot, controls: EmbedControls, captions: EmbedCaption[], onCancel: () => void) {
    this.stage = el('div', { className: 'stage', attrs: { part: 'stage', role: 'region' } });
    this.placeholder = el('div', { className: 'placeholder', text: 'Loading…' });
    this.message = el('div', { className: 'message', attrs: { part: 'message', role: 'alert' } });
    this.message.hidden = true;
    this.status = el('div', { className: 'status', attrs: { role: 'status', 'aria-live': 'polite' } });
    this.busyLabel = el('span');
    const cancel = el('button', { text: 'Cancel', attrs: { type: 'button', part: 'cancel' } });
    cancel.addEventListener('click', onCancel);
    this.busyBox = el('div', { className: 'busy', attrs: { part: 'progress' } }, this.busyLabel, cancel);
    this.busyBox.hidden = true;
    this.labels.push(el('div', { className: 'pane-label', attrs: { part: 'pane-label' } }));
    this.labels[0].hidden = true;
    this.stage.append(this.placeholder, this.message, this.busyBox, this.status, this.labels[0]);
    this.panes = el('div', { className: 'panes', attrs: { part: 'panes', 'data-count': '1' } }, this.stage);
    adoptStyles(root);
    root.append(el('div', { className: 'frame' }, this.panes, ...captions.map((c) => c.element), controls.element));
  }

  /** A pane beside the others (index 1 or more): the element its viewer draws in. */
  addPane(index: number): HTMLElement {
    const view = el('div', { className: 'pane-view' });
    const label = el('div', { className: 'pane-label', attrs: { part: 'pane-label' } });
    this.labels[index] = label;
    this.panes.append(el('div', { className: 'pane', attrs: { part: 'pane' } }, view, label));
    this.panes.dataset.count = String(this.panes.children.length);
    return view;
  }

  removePane(index: number): void {
    this.panes.children[index]?.remove();
    this.labels.length = index;
    this.panes.dataset.count = String(this.panes.children.length);
  }

  /** Each pane's label (scheme, level), the first's shown only beside others. */
  setPaneLabels(texts: string[]): void {
    texts.forEach((text, i) => {
      const label = this.labels[i];
      if (label && label.textContent !== text) label.textContent = text;
    });
    this.labels[0].hidden = texts.length < 2;
  }

  /** The stage's accessible name. */
  setLabel(label: string): void {
    this.stage.setAttribute('aria-label', label);
  }

  /** Shows the placeholder with `text` (while no message is shown), or hides it (null). */
  setPlaceholder(text: string | null): void {
    if (text !== null) this.placeholder.textContent = text;
    this.placeholder.hidden = text === null || !this.message.hidden;
  }

  showMessage(text: string): void {
    this.message.textContent = text;
    this.message.hidden = false;
    this.placeholder.hidden = true;
  }

  hideMessage(): void {
    this.message.hidden = true;
  }

  /** The busy box with `label` and Cancel, or none (null). */
  setBusy(label: string | null): void {
    this.busyBox.hidden = label === null;
    this.busyLabel.textContent = label ?? '';
  }

  /** Says `text` to screen readers (a polite live region). */
  announce(text: string): void {
    this.status.textContent = text;
  }
}

/**
 * The element's styles in its shadow root: a constructed style sheet, which
 * a page's Content-Security-Policy allows without 'unsafe-inline' (the
 * SubdivLab site's refuses inline styles), shared by every viewer on the
 * page; a `<style>` element where constructed sheets are missing.
 */
function adoptStyles(root: ShadowRoot): void {
  if ('adoptedStyleSheets' in root && 'replaceSync' in CSSStyleSheet.prototype) {
    sheet ??= new CSSStyleSheet();
    if (sheet.cssRules.length === 0) sheet.replaceSync(EMBED_CSS);
    root.adoptedStyleSheets = [...root.adoptedStyleSheets, sheet];
    return;
  }
  const style = document.createElement('style');
  style.textContent = EMBED_CSS;
  root.append(style);
}

let sheet: CSSStyleSheet | null = null;
