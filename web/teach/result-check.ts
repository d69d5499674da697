/**
 * Check my result: a student's own level (an OFF/OBJ file from their
 * program, read in the page and sent nowhere else) against the app's level
 * K of the control mesh under the chosen scheme: the verdict, its reasons,
 * the errors, each reference vertex coloured by the error of the result's
 * vertex matched to it, and the worst vertices, whose expected stencils the
 * inspector shows.
 */
import type { MeshComparison } from '../core/compare';
import type { ReadFormat } from '../core/mesh';
import { influenceColors } from '../render/level-graphics';
import type { SubdivViewer } from '../viewer/subdiv-viewer';

export interface CheckedResult {
  name: string;
  level: number;
  relativeTolerance: number;
  comparison: MeshComparison;
}

export interface CheckState {
  available: boolean;
  checked: CheckedResult | null;
}

export class ResultCheck {
  private checked: CheckedResult | null = null;
  private checkedId = 0;
  private readonly listeners = new Set<(state: CheckState) => void>();

  /**
   * `reach(k)` computes the levels up to k and shows level k (false when it
   * could not); `onError` hears of a file or a step that failed.
   */
  constructor(
    private readonly viewer: SubdivViewer,
    private readonly reach: (level: number) => Promise<boolean>,
    private readonly onError: (error: unknown) => void,
  ) {
    viewer.onChange(() => {
      // The checked level computed again (a new model, scheme or crease edit): the verdict is of another mesh.
      if (this.checked && viewer.levelId(this.checked.level) !== this.checkedId) this.checked = null;
      this.emit();
    });
  }

  get state(): CheckState {
    return { available: this.viewer.state.levelCount > 0, checked: this.checked };
  }

  onChange(listener: (state: CheckState) => void): () => void {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  }

  /** Checks `text` (file `name`, text or bytes) as level `level` of the shown model and scheme. */
  async check(
    name: string,
    text: string | Uint8Array,
    format: ReadFormat,
    level: number,
    relativeTolerance: number,
  ): Promise<void> {
    try {
      if (!(await this.reach(level))) return;
      const comparison = await this.viewer.checkResult(level, text, format, relativeTolerance);
      if (!comparison) return;
      this.checked = { name, level, relativeTolerance, comparison };
      this.checkedId = this.viewer.levelId(level);
      this.colour(level, comparison);
      this.emit();
    } catch (error) {
      this.onError(error);
    }
  }

  /**
   * Each reference vertex in the colour of the largest error among the
   * result's vertices matched to it (dark: none, yellow: the largest);
   * plain when every vertex is within the tolerance (rounding would be all
   * there is to see).
   */
  private colour(level: number, c: MeshComparison): void {
    if (c.maxError <= c.tolerance) {
      this.viewer.setLevelColors(level, null, 'check');
      return;
    }
    const count = this.viewer.buffersOf(level)?.positions.length ?? 0;
    const worst = new Float64Array(count / 3);
    for (let v = 0; v < c.errors.length; ++v) worst[c.matched[v]] = Math.max(worst[c.matched[v]], c.errors[v]);
    this.viewer.setLevelColors(level, influenceColors(worst, 0, c.maxError), 'check');
  }

  private emit(): void {
    const state = this.state;
    for (const listener of this.listeners) listener(state);
  }
}
