/**
 * The viewpoints **Save view** keeps across models and visits: a short list,
 * each named ("View 1", "View 2", …), in localStorage. An older SubdivLab
 * kept one view under `subdivlab.view`; that key is still read (its view
 * joins the list when the list lacks it) and still written with the last
 * view saved, so a page of either age finds the other's view.
 */
import { checkedView, parseViewState, type ViewState } from '../render/view-state';

export const VIEWS_STORAGE_KEY = 'subdivlab.views';
/** The one view older versions kept. */
export const LEGACY_VIEW_KEY = 'subdivlab.view';
/** Most views kept; saving one more drops the oldest. */
export const MAX_SAVED_VIEWS = 12;

export interface SavedView {
  name: string;
  view: ViewState;
}

function sameView(a: ViewState, b: ViewState): boolean {
  const ka = [...a.position, ...a.target, ...a.up];
  const kb = [...b.position, ...b.target, ...b.up];
  return ka.every((x, i) => x === kb[i]);
}

/** `views` with `view` added last, named "View n" with the smallest n not taken (oldest dropped past the limit). */
export function addView(views: readonly SavedView[], view: ViewState): SavedView[] {
  const taken = new Set(views.map((v) => v.name));
  let n = 1;
  while (taken.has(`View ${n}`)) n++;
  return [...views, { name: `View ${n}`, view }].slice(-MAX_SAVED_VIEWS);
}

/** `views` without the one named `name`. */
export function removeView(views: readonly SavedView[], name: string): SavedView[] {
  return views.filter((v) => v.name !== name);
}

/** Reads a stored list; entries that are not views are left out. */
export function parseViews(text: string | null): SavedView[] {
  if (!text) return [];
  let value: unknown;
  try {
    value = JSON.parse(text);
  } catch {
    // Not JSON: no views.
    return [];
  }
  if (!Array.isArray(value)) return [];
  const views: SavedView[] = [];
  for (const entry of value) {
    const view = checkedView((entry as { view?: unknown })?.view);
    const name = (entry as { name?: unknown })?.name;
    if (view && typeof name === 'string' && name.trim() !== '' && !views.some((v) => v.name === name)) {
      views.push({ name, view });
    }
  }
  return views.slice(-MAX_SAVED_VIEWS);
}

/**
 * The saved views: the list, with the older single view added when the list
 * does not hold it (it was saved by an older version, or before any list).
 */
export function loadViews(storage: Storage = localStorage): SavedView[] {
  const views = parseViews(storage.getItem(VIEWS_STORAGE_KEY));
  const legacy = parseViewState(storage.getItem(LEGACY_VIEW_KEY));
  if (legacy && !views.some((v) => sameView(v.view, legacy))) return addView(views, legacy);
  return views;
}

/** Stores `views`, and the last of them under the older key. */
export function storeViews(views: readonly SavedView[], storage: Storage = localStorage): void {
  storage.setItem(VIEWS_STORAGE_KEY, JSON.stringify(views));
  const last = views.at(-1);
  if (last) storage.setItem(LEGACY_VIEW_KEY, JSON.stringify(last.view));
  else storage.removeItem(LEGACY_VIEW_KEY);
}
