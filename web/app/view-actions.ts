/**
 * What the view controls do (ui/view-controls.ts): Fit, the canonical
 * views, the saved views kept in localStorage (saved-views.ts) and the line
 * width.
 */
import { type CanonicalView, nextCanonicalView } from '../render/fit';
import { ViewControls } from '../ui/view-controls';
import type { SubdivViewer } from '../viewer/subdiv-viewer';
import { addView, loadViews, removeView, type SavedView, storeViews } from './saved-views';

export class ViewActions {
  readonly controls: ViewControls;
  private views: SavedView[] = loadViews();
  /** The saved view picked in the menu (the one Restore goes to): the last saved at first. */
  private selected: string | null = this.views.at(-1)?.name ?? null;
  /** The canonical view shown last (V steps on from it). */
  private canonical: CanonicalView | null = null;

  /** `frame` fits the views (the side-by-side panes together; default: the viewer alone). */
  constructor(
    private readonly viewer: SubdivViewer,
    private readonly frame: (view?: CanonicalView) => void = (view) => viewer.fitView(view),
  ) {
    this.controls = new ViewControls({
      onFit: () => this.fit(),
      onCanonical: (view) => this.fit(view),
      onSaveView: () => this.save(),
      onRestoreView: (name) => this.restore(name),
      onDeleteView: (name) => this.remove(name),
      onLineWidth: (width) => viewer.setLineWidth(width),
    });
  }

  /** Frames what is shown, from where the camera looks or from a canonical view. */
  fit(view?: CanonicalView): void {
    this.canonical = view ?? null;
    this.frame(view);
  }

  /** The V key: the next canonical view. */
  nextCanonical(): void {
    this.fit(nextCanonicalView(this.canonical));
  }

  /** Saves the viewpoint as a new named view and picks it. */
  save(): void {
    this.views = addView(this.views, this.viewer.getView());
    this.selected = this.views.at(-1)?.name ?? null;
    storeViews(this.views);
    this.update();
  }

  /** Goes to the saved view `name` (the one picked when not given). */
  restore(name = this.selected ?? ''): void {
    const saved = this.views.find((v) => v.name === name);
    if (!saved) return;
    this.selected = name;
    this.viewer.setView(saved.view);
  }

  remove(name: string): void {
    this.views = removeView(this.views, name);
    this.selected = this.views.at(-1)?.name ?? null;
    storeViews(this.views);
    this.update();
  }

  /** Names of the saved views, oldest first. */
  get names(): string[] {
    return this.views.map((v) => v.name);
  }

  update(): void {
    this.controls.update(this.names, this.selected, this.viewer.state.lineWidth);
  }
}
