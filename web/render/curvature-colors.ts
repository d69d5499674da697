/**
 * Colours of signed curvature: a diverging map (ColorBrewer's RdBu, blue
 * for negative, near white for 0, red for positive) over a range symmetric
 * about 0, whose end is a robust largest magnitude — the larger of the
 * 2nd and 98th percentiles' magnitudes — so that a few spikes (a cube's
 * corners on a subdivided cube, a bad triangle) do not wash the rest out;
 * values beyond it take the end colour (clamped).
 */
import { Color } from 'three';

/** RdBu at seven stops, from the most negative to the most positive. */
export const DIVERGING_STOPS = ['#2166ac', '#67a9cf', '#d1e5f0', '#f7f7f7', '#fddbc7', '#ef8a62', '#b2182b'] as const;

/** The colour of a vertex that has no curvature (on the border). */
export const NO_CURVATURE_COLOR = '#a6a6a6';

/** The percentiles whose magnitudes bound the range. */
export const ROBUST_PERCENTILES = [2, 98] as const;

/** The colour of t in [-1, 1] on {@link DIVERGING_STOPS} (clamped). */
export function divergingColor(t: number): Color {
  const x = ((Math.min(Math.max(t, -1), 1) + 1) / 2) * (DIVERGING_STOPS.length - 1);
  const i = Math.min(Math.floor(x), DIVERGING_STOPS.length - 2);
  return new Color(DIVERGING_STOPS[i]).lerp(new Color(DIVERGING_STOPS[i + 1]), x - i);
}

/** The value at percentile p (0..100) of sorted `values`, by linear interpolation between ranks. */
function percentile(sorted: Float64Array, p: number): number {
  if (sorted.length === 0) return 0;
  const at = (p / 100) * (sorted.length - 1);
  const i = Math.floor(at);
  const j = Math.min(i + 1, sorted.length - 1);
  return sorted[i] + (sorted[j] - sorted[i]) * (at - i);
}

export interface CurvatureColours {
  /** r g b in 0..1 per vertex, as setLevelColors takes them. */
  rgb: Float32Array;
  /** The range's end: colours run from −limit (blue) to +limit (red). */
  limit: number;
  /** The least and largest finite values (before clamping). */
  min: number;
  max: number;
  /** Vertices without a value (NaN: border), coloured {@link NO_CURVATURE_COLOR}. */
  uncoloured: number;
  /** Vertices whose value lies beyond ±limit (drawn in the end colour). */
  clamped: number;
}

/** Colours `values` (NaN: none) on the diverging map over their robust symmetric range. */
export function curvatureColours(values: Float64Array): CurvatureColours {
  const finite = values.filter((x) => Number.isFinite(x)).sort();
  const [low, high] = ROBUST_PERCENTILES.map((p) => percentile(finite, p));
  const limit = Math.max(Math.abs(low), Math.abs(high));
  const rgb = new Float32Array(3 * values.length);
  const none = new Color(NO_CURVATURE_COLOR);
  let uncoloured = 0;
  let clamped = 0;
  for (let v = 0; v < values.length; v++) {
    const x = values[v];
    let c = none;
    if (!Number.isFinite(x)) uncoloured++;
    else {
      if (Math.abs(x) > limit) clamped++;
      c = divergingColor(limit > 0 ? x / limit : 0);
    }
    rgb[3 * v] = c.r;
    rgb[3 * v + 1] = c.g;
    rgb[3 * v + 2] = c.b;
  }
  const min = finite.length > 0 ? finite[0] : 0;
  const max = finite.length > 0 ? finite[finite.length - 1] : 0;
  return { rgb, limit, min, max, uncoloured, clamped };
}
