/**
 * Skip links: the page's first Tab stops, shown only while focused, each
 * taking the keyboard to a part of the page (the view, the controls) past
 * the header's buttons.
 */
import { el } from './dom';

export interface SkipTarget {
  label: string;
  testId: string;
  /** The element focused; it needs an id (the link's href) and a tabindex. */
  target: HTMLElement;
}

/** The links to `targets`, in order, as one list for the top of the page. */
export function skipLinks(targets: readonly SkipTarget[]): HTMLElement {
  const links = targets.map(({ label, testId, target }) => {
    const link = el('a', { testId, className: 'skip-link', text: label, attrs: { href: `#${target.id}` } });
    // Focus moves; the hash, which holds the app's state, stays as it is.
    link.addEventListener('click', (event) => {
      event.preventDefault();
      target.focus();
    });
    return link;
  });
  return el('div', { className: 'skip-links' }, ...links);
}
