/**
 * Side by side in a `<subdiv-viewer>` (attribute `beside`): the app's
 * SideBySide (web/teach/) over the element's viewer, with panes for the
 * schemes named, cameras linked and levels together (the element's
 * `levels`); with `distance` (on by default), the symmetric Hausdorff
 * distance between the first two panes in a caption (part `distance`) and a
 * `distance` event, and both surfaces coloured by it.
 */
import { distanceText, hausdorffText, SideBySide, type SideBySideState } from '../teach/side-by-side';
import { schemeInfo } from '../viewer/scheme-info';
import { SubdivViewer } from '../viewer/subdiv-viewer';
import type { EmbedCaption } from './embed-caption';
import type { EmbedChrome } from './embed-chrome';
import type { DistanceDetail } from './embed-events';
import type { EmbedState } from './embed-state';

/** What the panes need from their element. */
export interface PanesHost {
  readState(): EmbedState;
  /** Reports a failed measurement (message and `error` event). */
  fail(error: unknown): void;
  dispatch(type: 'distance', detail: DistanceDetail): void;
}

export class EmbedPanes {
  private readonly sides: SideBySide;
  private lastDistance: unknown = null;

  constructor(
    viewer: SubdivViewer,
    private readonly host: PanesHost,
    private readonly chrome: EmbedChrome,
    private readonly caption: EmbedCaption,
  ) {
    this.sides = new SideBySide(
      viewer,
      {
        addPane: (index) => new SubdivViewer(chrome.addPane(index)),
        removePane: (index) => chrome.removePane(index),
      },
      (error) => host.fail(error),
    );
    this.sides.onChange((state) => this.show(state));
  }

  /** Brings the panes to the attributes: the schemes beside, the distance on or off, the background (the first pane's). */
  apply(background: string | null, dark: boolean): void {
    const want = this.host.readState();
    const beside = this.sides.beside();
    if (beside.join(' ') !== want.beside.join(' ')) this.sides.setBeside(want.beside);
    if (this.sides.state.colours !== want.distance) this.sides.setColours(want.distance);
    // Render mode and overlays follow the first pane (SideBySide); the background is the element's.
    for (const pane of this.sides.viewers().slice(1)) pane.view.setBackground(background, dark);
  }

  /** Frees the panes' GPU copies (the element is far out of view), or draws them again. */
  releaseGpu(release: boolean): void {
    for (const pane of this.sides.viewers().slice(1)) {
      if (release) pane.releaseGpu();
      else pane.view.requestRender();
    }
  }

  /** Stops the panes' steps. */
  cancel(): void {
    this.sides.cancel();
  }

  /** Removes the panes (the element left the page). */
  dispose(): void {
    this.sides.setBeside([]);
  }

  private show(state: SideBySideState): void {
    this.chrome.setPaneLabels(
      state.count < 2
        ? []
        : state.panes.map((p) => {
            const level = p.viewer.levelCount > 0 ? ` · level ${p.viewer.level}` : '';
            const tags = p.ignoresTags ? ' · creases not applied' : '';
            const problem = p.message ? ` · ${p.message}` : '';
            return `${schemeInfo(p.scheme).label}${level}${tags}${problem}`;
          }),
    );
    const d = state.distance;
    const want = this.host.readState();
    if (state.count < 2 || !want.distance) {
      this.caption.show(null);
      return;
    }
    if (!d) {
      this.caption.show({ line: state.message || 'Measuring the distance between the surfaces…', hint: true });
      return;
    }
    const names = d.panes.map((p, i) => `${schemeInfo(state.panes[p]?.scheme ?? '').label} ${d.levels[i]}`);
    this.caption.show({
      line:
        `Hausdorff distance, ${names[0]} to ${names[1]}: ${hausdorffText(d)}` +
        (d.distance > d.errorBound ? ` (${(100 * d.relative).toPrecision(3)} % of the diagonal)` : ''),
      legend: ['0', distanceText(d.distance)],
    });
    if (d === this.lastDistance) return;
    this.lastDistance = d;
    this.host.dispatch('distance', {
      distance: d.distance,
      relative: d.relative,
      diagonal: d.diagonal,
      errorBound: d.errorBound,
      schemes: [state.panes[d.panes[0]].scheme, state.panes[d.panes[1]].scheme],
      levels: d.levels,
    });
  }
}
