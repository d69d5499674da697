/**
 * How much memory a subdivision step may take before the app asks first.
 * The core predicts its own peak (WASM heap, at most 4 GB); the page then
 * keeps a JS copy of the mesh, render buffers and normals, and the GPU
 * another copy. Browsers do not say how much a tab may use, so the budget
 * is a share of the device's memory where Chrome reports it.
 */
import type { SizePrediction } from '../core/mesh';

const GiB = 1024 ** 3;

/** Default budget: half the reported device memory, between 512 MiB and 2 GiB. */
export function defaultMemoryBudget(): number {
  const deviceGiB = (navigator as Navigator & { deviceMemory?: number }).deviceMemory ?? 4;
  return Math.min(2 * GiB, Math.max(0.5 * GiB, (deviceGiB * GiB) / 2));
}

/**
 * Bytes a step's result needs outside the WASM heap: the mesh (float64
 * positions, uint32 face sizes and corners), render buffers (float32
 * positions and normals, fanned triangles, polygon edges, triangle→face).
 * For a closed mesh the corners number 2E and the fanned triangles 2E − 2F.
 */
export function pageBytes(p: SizePrediction): number {
  const corners = 2 * p.edges;
  const triangles = Math.max(0, corners - 2 * p.faces);
  const mesh = 24 * p.vertices + 4 * p.faces + 4 * corners;
  const render = 24 * p.vertices + 12 * triangles + 8 * p.edges + 4 * triangles;
  // The GPU holds positions, normals and both index buffers once more.
  const gpu = 24 * p.vertices + 12 * triangles + 8 * p.edges;
  return mesh + render + gpu;
}

/** Total estimate for a step: the core's peak plus what the page keeps. */
export function stepBytes(p: SizePrediction): number {
  return p.peakBytes + pageBytes(p);
}

/** "1.2 GB", "350 MB", "12 kB". */
export function formatBytes(bytes: number): string {
  if (bytes >= 1e9) return `${(bytes / 1e9).toFixed(1)} GB`;
  if (bytes >= 1e6) return `${Math.round(bytes / 1e6)} MB`;
  return `${Math.max(1, Math.round(bytes / 1e3))} kB`;
}
