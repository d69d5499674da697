/** What Cancel (or Esc) says it did, in the notice bar. */
import type { BusyState } from '../viewer/subdiv-viewer';

/**
 * The sentence for cancelling `busy` while level `shown` of a model is shown
 * (`shown` null: no model yet), e.g. "Cancelled: level 3 was not computed;
 * level 2 is shown."; null when nothing was running.
 */
export function cancelMessage(busy: BusyState | null, shown: number | null): string | null {
  if (!busy) return null;
  const after = shown === null ? 'no model is shown.' : `level ${shown} is shown.`;
  if (busy.kind === 'subdivide' && busy.level !== undefined) {
    return `Cancelled: level ${busy.level} was not computed; ${after}`;
  }
  if (busy.kind === 'load') {
    const what = busy.label.replace(/^Loading\s+/, '').replace(/…$/, '');
    return `Cancelled: ${what} was not loaded; ${shown === null ? 'no model is shown.' : 'the previous model is shown.'}`;
  }
  // A tool's request or an export: its label says what it was doing.
  return `Cancelled: ${busy.label.replace(/…$/, '').replace(/^./, (c) => c.toLowerCase())} stopped; ${after}`;
}
