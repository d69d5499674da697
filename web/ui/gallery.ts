/** The gallery of sample meshes: one button per sample. */
import { dropdown, el } from './dom';

/** A sample mesh the gallery offers. */
export interface Sample {
  /** Used in test ids (`gallery.cube`). */
  id: string;
  /** Path relative to the page. */
  path: string;
  label: string;
  /** One line: what it is good for. */
  note: string;
}

export function createGallery(samples: readonly Sample[], onPick: (sample: Sample) => void): HTMLElement {
  const list = el('ul', { className: 'gallery' });
  for (const sample of samples) {
    const b = el(
      'button',
      { testId: `gallery.${sample.id}`, attrs: { type: 'button', 'aria-label': `Open sample ${sample.label}` } },
      el('span', { className: 'gallery-label', text: sample.label }),
      el('span', { className: 'gallery-note', text: sample.note }),
    );
    b.addEventListener('click', () => onPick(sample));
    list.append(el('li', {}, b));
  }
  return dropdown('Samples', 'gallery', list);
}
