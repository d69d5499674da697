/** The one viewpoint **Save view** keeps across models and visits (localStorage). */
import { parseViewState, type ViewState } from '../render/view-state';

const VIEW_STORAGE_KEY = 'subdivlab.view';

export function saveView(view: ViewState): void {
  localStorage.setItem(VIEW_STORAGE_KEY, JSON.stringify(view));
}

/** The saved viewpoint, or null when there is none (or it is unreadable). */
export function savedView(): ViewState | null {
  return parseViewState(localStorage.getItem(VIEW_STORAGE_KEY));
}
