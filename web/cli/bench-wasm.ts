/**
 * WASM side of `npm run bench` (scripts/bench.mjs): times one subdivision step
 * of each scheme through the TS API in Node — the same calls the app and the
 * CLI make, typed-array copies in and out included. Bundled beside the CLI
 * into build/cli/bench-wasm.mjs.
 */
import { readFileSync } from 'node:fs';
import { performance } from 'node:perf_hooks';
import { initNode } from '../core/init-node';
import type { SchemeName } from '../core/mesh';
import { formatFromFileName, parseMesh, subdivide } from '../core/subdiv-core';

/** Timings of one scheme, as the native bench prints them. */
export interface SchemeTiming {
  scheme: string;
  faces: number;
  median_ms: number;
  runs_ms: number[];
}

function median(values: number[]): number {
  const v = [...values].sort((a, b) => a - b);
  const n = v.length;
  return n % 2 ? v[(n - 1) / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

/** One untimed warm-up run and `runs` timed runs of one level of each scheme on the mesh at `path`. */
export async function benchWasm(path: string, runs: number, schemes: SchemeName[]): Promise<SchemeTiming[]> {
  await initNode();
  const mesh = parseMesh(readFileSync(path, 'utf8'), formatFromFileName(path) ?? 'off');
  return schemes.map((scheme) => {
    const times: number[] = [];
    let faces = 0;
    for (let r = 0; r <= runs; r++) {
      const start = performance.now();
      const out = subdivide(mesh, { scheme, levels: 1 });
      const ms = performance.now() - start;
      faces = out.faceSizes.length;
      if (r > 0) times.push(ms);
    }
    return { scheme, faces, median_ms: median(times), runs_ms: times };
  });
}
