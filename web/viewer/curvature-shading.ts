/**
 * The curvature render modes: while one is chosen, the shown level's
 * vertices take the colours of their curvature (asked of the core's worker
 * once a level, render/curvature-colors.ts colours them) and a colour bar
 * over the view says what they mean; leaving the mode takes them away.
 */
import type { CurvatureKind, VertexCurvature } from '../core/curvature';
import { ColourLegend } from '../render/colour-legend';
import { curvatureColours, DIVERGING_STOPS, ROBUST_PERCENTILES } from '../render/curvature-colors';
import type { RenderMode } from '../render/render-mode';

/** The curvature a render mode colours by (null: it colours by none). */
export function curvatureKindOf(mode: RenderMode): CurvatureKind | null {
  if (mode === 'mean-curvature') return 'mean';
  if (mode === 'gaussian-curvature') return 'gaussian';
  return null;
}

const TITLES: Record<CurvatureKind, string> = {
  mean: 'Mean curvature H (1/length)',
  gaussian: 'Gaussian curvature K (1/length²)',
};

/** A number for the bar: three significant digits, with an exponent when very small or large. */
export function legendNumber(x: number): string {
  if (x === 0) return '0';
  const a = Math.abs(x);
  return a >= 1e-3 && a < 1e5 ? Number(x.toPrecision(3)).toString() : x.toExponential(2);
}

/** 2 → '2nd', 98 → '98th'. */
function ordinal(n: number): string {
  const teen = n % 100 >= 11 && n % 100 <= 13;
  const suffix = teen ? 'th' : (['th', 'st', 'nd', 'rd'][n % 10] ?? 'th');
  return `${n}${suffix}`;
}

/** What the shading asks of its viewer. */
export interface CurvatureHost {
  readonly renderMode: RenderMode;
  /** The shown level's number and identity (levelId: another number once it is recomputed). */
  readonly shownLevel: { k: number; id: number } | null;
  /** How many levels exist (0..count − 1). */
  readonly levelCount: number;
  curvature(k: number): Promise<VertexCurvature | null>;
  setCurvatureColours(k: number, rgb: Float32Array | null): void;
}

export class CurvatureShading {
  readonly legend: ColourLegend;
  /** Levels coloured by curvature (by number), to uncolour when the mode ends. */
  private readonly coloured = new Set<number>();
  /** Bumped by each update, so that an answer that comes after a later update is dropped. */
  private turn = 0;

  constructor(
    container: HTMLElement,
    private readonly host: CurvatureHost,
  ) {
    this.legend = new ColourLegend(container);
  }

  /** Follows the render mode and shown level (after either changes); resolves once the colours show. */
  async update(): Promise<void> {
    const turn = ++this.turn;
    const kind = curvatureKindOf(this.host.renderMode);
    const shown = this.host.shownLevel;
    if (!kind || !shown) {
      this.clear();
      return;
    }
    let curvature: VertexCurvature | null = null;
    try {
      curvature = await this.host.curvature(shown.k);
    } catch {
      // A cancelled or failed request: the surface keeps its colours, and the next update asks again.
      return;
    }
    const now = this.host.shownLevel;
    if (turn !== this.turn || !curvature || now?.id !== shown.id) return;
    const values = curvature[kind];
    const c = curvatureColours(values);
    this.host.setCurvatureColours(shown.k, c.rgb);
    this.coloured.add(shown.k);
    const limit = legendNumber(c.limit);
    const [p0, p1] = ROBUST_PERCENTILES.map(ordinal);
    const notes = [
      `Range ±${limit}: the larger magnitude of the ${p0} and ${p1} percentiles; ${c.clamped} vertices beyond it clamped (all: ${legendNumber(c.min)} to ${legendNumber(c.max)}).`,
    ];
    if (c.uncoloured > 0) notes.push(`${c.uncoloured} border vertices grey (no curvature there).`);
    this.legend.show({
      title: `${TITLES[kind]}, level ${shown.k}`,
      stops: DIVERGING_STOPS,
      low: c.limit > 0 ? `−${limit}` : '0',
      middle: '0',
      high: c.limit > 0 ? `+${limit}` : '0',
      note: notes.join(' '),
    });
  }

  /** Takes the curvature colours away from every level and hides the bar. */
  private clear(): void {
    for (const k of this.coloured) if (k < this.host.levelCount) this.host.setCurvatureColours(k, null);
    this.coloured.clear();
    this.legend.hide();
  }

  dispose(): void {
    this.legend.dispose();
  }
}
