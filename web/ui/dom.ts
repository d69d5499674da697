/**
 * A small element builder. Text is always inserted as text nodes
 * (textContent), never parsed as markup: file names and anything quoted
 * from a file are shown as typed.
 */
export interface ElementProps {
  /** data-testid, dotted (`controls.scheme`). */
  testId?: string;
  className?: string;
  text?: string;
  attrs?: Record<string, string>;
}

export function el<K extends keyof HTMLElementTagNameMap>(
  tag: K,
  props: ElementProps = {},
  ...children: (Node | string)[]
): HTMLElementTagNameMap[K] {
  const element = document.createElement(tag);
  if (props.testId) element.dataset.testid = props.testId;
  if (props.className) element.className = props.className;
  if (props.text !== undefined) element.textContent = props.text;
  for (const [name, value] of Object.entries(props.attrs ?? {})) element.setAttribute(name, value);
  element.append(...children);
  return element;
}

/** A button with a visible label (its accessible name) and a click handler. */
export function button(label: string, testId: string, onClick: () => void, title?: string): HTMLButtonElement {
  const b = el('button', { testId, text: label, attrs: { type: 'button', ...(title ? { title } : {}) } });
  b.addEventListener('click', onClick);
  return b;
}

/** A labelled panel section with a heading. */
export function section(title: string, testId: string, ...children: Node[]): HTMLElement {
  const id = `${testId.replace(/\./g, '-')}-heading`;
  return el(
    'section',
    { testId, className: 'panel', attrs: { 'aria-labelledby': id } },
    el('h2', { text: title, attrs: { id } }),
    ...children,
  );
}

let nextId = 0;
/** A unique element id for label/control pairs (several viewers may share a page). */
export function uniqueId(prefix: string): string {
  nextId++;
  return `${prefix}-${nextId}`;
}

/** A header drop-down: a <details> whose summary is the button; closes after a choice or on Escape. */
export function dropdown(label: string, testId: string, ...children: Node[]): HTMLDetailsElement {
  const body = el('div', { className: 'dropdown-body' }, ...children);
  const details = el('details', { testId, className: 'dropdown' }, el('summary', { text: label }), body);
  body.addEventListener('click', (event) => {
    if (!(event.target as HTMLElement).closest('button')) return;
    // The chosen button disappears with the menu: give keyboard focus back to the menu's button.
    const hadFocus = body.contains(document.activeElement);
    details.open = false;
    if (hadFocus) details.querySelector('summary')?.focus();
  });
  // Like a menu, a click elsewhere closes it.
  document.addEventListener('pointerdown', (event) => {
    if (details.open && !details.contains(event.target as Node)) details.open = false;
  });
  details.addEventListener('keydown', (event) => {
    if (event.key === 'Escape' && details.open) {
      event.preventDefault();
      details.open = false;
      details.querySelector('summary')?.focus();
    }
  });
  return details;
}

/**
 * A labelled field for a vertex number (a row: label, input): `onVertex`
 * hears each whole number entered (Enter or leaving the field).
 */
export function vertexField(
  label: string,
  testId: string,
  onVertex: (vertex: number) => void,
): { row: HTMLElement; input: HTMLInputElement } {
  const id = uniqueId(testId.replace(/\./g, '-'));
  const input = el('input', {
    testId,
    attrs: { id, type: 'number', min: '0', step: '1', inputmode: 'numeric' },
  });
  input.addEventListener('change', () => {
    const v = Number(input.value);
    if (input.value !== '' && Number.isInteger(v)) onVertex(v);
  });
  return { row: el('div', { className: 'row' }, el('label', { attrs: { for: id }, text: label }), input), input };
}
