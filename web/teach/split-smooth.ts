/**
 * Split, then smooth: the shown level drawn anywhere between its split
 * alone (the linear scheme's points: midpoints and centroids of level
 * k − 1) and its smoothed points, by a slider or animated, so that a step
 * reads as a refinement followed by averaging. For the schemes on the PQQ
 * and PTQ hosts (Catmull-Clark, Loop, custom rules there).
 */
import { linearTwin, schemeInfo } from '../viewer/scheme-info';
import type { SubdivViewer } from '../viewer/subdiv-viewer';

export interface SplitState {
  /** A level ≥ 1 of a scheme with a split of its own is shown. */
  available: boolean;
  /** 0: the split alone, 1: the smoothed level. */
  t: number;
  animating: boolean;
  message: string;
}

/** How long the animation from the split to the smoothed level takes, in ms. */
const ANIMATION_MS = 1600;

export class SplitSmooth {
  private t = 1;
  private animating = false;
  /** The split points of the shown level, once fetched, and which level (object) they are of. */
  private split: { key: number; points: Promise<Float32Array | null> } | null = null;
  private frame = 0;
  private readonly listeners = new Set<(state: SplitState) => void>();

  constructor(
    private readonly viewer: SubdivViewer,
    private readonly onError: (error: unknown) => void,
  ) {
    viewer.onChange(() => {
      // Another level (or model, or scheme) is shown at its own points: the slider follows.
      if (this.split && this.split.key !== this.key()) {
        this.stop();
        this.split = null;
        this.t = 1;
      }
      this.emit();
    });
  }

  get state(): SplitState {
    const s = this.viewer.state;
    const twin = linearTwin(s.scheme, this.viewer.schemeRulesHost());
    const available = s.levelCount > 0 && s.level >= 1 && twin !== null && !s.busy;
    let message = '';
    if (!twin) message = `${schemeInfo(s.scheme).label} does not split, then smooth: try Catmull-Clark or Loop.`;
    else if (s.level < 1) message = 'Subdivide, then slide from the split (0) to the smoothed level (1).';
    return { available, t: this.t, animating: this.animating, message };
  }

  onChange(listener: (state: SplitState) => void): () => void {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  }

  /** Draws the shown level at `t` of the way from its split to its smoothed points. */
  async setT(t: number): Promise<void> {
    this.stop();
    await this.draw(Math.min(Math.max(t, 0), 1));
  }

  /** Plays the step from the split to the smoothed level. */
  animate(): void {
    this.stop();
    this.animating = true;
    const start = performance.now();
    const tick = () => {
      const t = Math.min(1, (performance.now() - start) / ANIMATION_MS);
      void this.draw(t);
      if (t < 1 && this.animating) this.frame = requestAnimationFrame(tick);
      else this.stop();
    };
    this.frame = requestAnimationFrame(tick);
    this.emit();
  }

  private stop(): void {
    cancelAnimationFrame(this.frame);
    if (this.animating) {
      this.animating = false;
      this.emit();
    }
  }

  private async draw(t: number): Promise<void> {
    if (!this.state.available && t !== 1) return;
    const key = this.key();
    if (this.split?.key !== key) this.split = { key, points: this.viewer.splitPoints() };
    try {
      const points = await this.split.points;
      if (!points || this.key() !== key) return;
      this.t = t;
      this.viewer.setSplitBlend(points, t);
      this.emit();
    } catch (error) {
      this.split = null;
      this.onError(error);
    }
  }

  /** The shown level object: another when the level, model, scheme or tags change. */
  private key(): number {
    return this.viewer.levelId();
  }

  private emit(): void {
    const state = this.state;
    for (const listener of this.listeners) listener(state);
  }
}
