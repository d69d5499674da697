/**
 * WASM side of `npm run bench` (scripts/bench.mjs): times one subdivision step
 * of each scheme through the TS API in Node — the same calls the app and the
 * CLI make, typed-array copies in and out included. Bundled beside the CLI
 * into build/cli/bench-wasm.mjs.
 */
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { performance } from 'node:perf_hooks';
import { initNode } from '../core/init-node';
import type { Mesh, MeshFormat, SchemeName, SubdivideOptions } from '../core/mesh';
import { parseRuleSetText } from '../core/rule-set';
import {
  exportMesh,
  exportMeshChunks,
  formatFromFileName,
  inspectMesh,
  parseMesh,
  predictSize,
  subdivide,
} from '../core/subdiv-core';

/** Timings of one scheme, as the native bench prints them, with the core's predicted peak. */
export interface SchemeTiming {
  scheme: string;
  faces: number;
  median_ms: number;
  runs_ms: number[];
  /** predictSize's peak bytes for the run: the memory model, which bounds the measured peak (core tests). */
  peak_bytes: number;
  /**
   * The same run on CGAL's hosts (option cgalHosts: the product before the
   * fast hosts), when asked: its median ms and predicted peak bytes.
   */
  cgal_hosts?: { median_ms: number; runs_ms: number[]; peak_bytes: number };
}

function median(values: number[]): number {
  const v = [...values].sort((a, b) => a - b);
  const n = v.length;
  return n % 2 ? v[(n - 1) / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

/**
 * The options of a bench scheme: a scheme's name, or `custom:NAME`, the
 * custom scheme with the rule file `rulesDir`/NAME.json (a preset of the
 * rules panel; the native bench runs the same preset).
 */
function benchOptions(scheme: string, levels: number, rulesDir: string): SubdivideOptions {
  const custom = /^custom:(.+)$/.exec(scheme);
  if (!custom) return { scheme: scheme as SchemeName, levels };
  const rules = parseRuleSetText(readFileSync(join(rulesDir, `${custom[1]}.json`), 'utf8'));
  return { scheme: 'custom', levels, rules };
}

/** One untimed warm-up run and `runs` timed runs of `subdivide(mesh, options)`: the times and the faces made. */
function timeRuns(mesh: Mesh, options: SubdivideOptions, runs: number): { times: number[]; faces: number } {
  const times: number[] = [];
  let faces = 0;
  for (let r = 0; r <= runs; r++) {
    const start = performance.now();
    const out = subdivide(mesh, options);
    const ms = performance.now() - start;
    faces = out.faceSizes.length;
    if (r > 0) times.push(ms);
  }
  return { times, faces };
}

/**
 * One untimed warm-up run and `runs` timed runs of `levels` levels of each
 * scheme (see benchOptions) on the mesh at `path`; with `cgalRuns`, as
 * many of the same on CGAL's hosts (the product before its fast hosts),
 * which must make as many faces.
 */
export async function benchWasm(
  path: string,
  runs: number,
  schemes: string[],
  levels = 1,
  rulesDir = '',
  cgalRuns = 0,
): Promise<SchemeTiming[]> {
  await initNode();
  const mesh = parseMesh(readFileSync(path, 'utf8'), formatFromFileName(path) ?? 'off');
  return schemes.map((scheme) => {
    const options = benchOptions(scheme, levels, rulesDir);
    const { times, faces } = timeRuns(mesh, options, runs);
    const timing: SchemeTiming = {
      scheme,
      faces,
      median_ms: median(times),
      runs_ms: times,
      peak_bytes: predictSize(mesh, options).peakBytes,
    };
    if (cgalRuns > 0) {
      const cgal = { ...options, cgalHosts: true };
      const before = timeRuns(mesh, cgal, cgalRuns);
      if (before.faces !== faces) throw new Error(`${scheme}: CGAL's hosts make ${before.faces} faces, not ${faces}`);
      timing.cgal_hosts = {
        median_ms: median(before.times),
        runs_ms: before.times,
        peak_bytes: predictSize(mesh, cgal).peakBytes,
      };
    }
    return timing;
  });
}

/** Parse and write speed of one mesh in one format. */
export interface IoTiming {
  mesh: string;
  format: MeshFormat;
  bytes: number;
  parse_ms: number;
  parse_mb_s: number;
  write_ms: number;
  write_mb_s: number;
}

/** A mesh to time: a file, or that file after `levels` Loop steps (a larger text). */
export interface IoSource {
  name: string;
  path: string;
  loopLevels?: number;
}

/**
 * Parse and write MB/s (10^6 bytes of text per second, medians of `runs`
 * after a warm-up) through the TS API as the app and the CLI call it: parsing
 * from a JS string, writing to the pieces an export saves.
 */
export async function benchIo(sources: IoSource[], runs: number): Promise<IoTiming[]> {
  await initNode();
  const rows: IoTiming[] = [];
  for (const source of sources) {
    let mesh = parseMesh(readFileSync(source.path, 'utf8'), formatFromFileName(source.path) ?? 'off');
    if (source.loopLevels) mesh = subdivide(mesh, { scheme: 'loop', levels: source.loopLevels });
    for (const format of ['off', 'obj'] as MeshFormat[]) {
      const text = exportMesh(mesh, format);
      const bytes = text.length;
      const time = (work: () => void): number => {
        const times: number[] = [];
        for (let r = 0; r <= runs; r++) {
          const start = performance.now();
          work();
          if (r > 0) times.push(performance.now() - start);
        }
        return median(times);
      };
      const parse_ms = time(() => parseMesh(text, format));
      const write_ms = time(() => exportMeshChunks(mesh, format));
      rows.push({
        mesh: source.name,
        format,
        bytes,
        parse_ms,
        parse_mb_s: bytes / 1e3 / parse_ms,
        write_ms,
        write_mb_s: bytes / 1e3 / write_ms,
      });
    }
  }
  return rows;
}

/** One of Inspect's computations on one mesh: its figure (pairs, radius, hull vertices, width) and the core's milliseconds. */
export interface InspectTiming {
  computation: 'self-intersections' | 'sphere' | 'hull' | 'width';
  figure: number;
  ms: number;
  skipped: boolean;
}

/**
 * Each of Inspect's computations alone on the mesh at `path` (or its level
 * `loopLevels` of Loop, triangulated first), in the WASM core, as
 * bench_inspect.cpp does natively: one run each, the core's own times.
 */
export async function benchInspect(
  path: string,
  loopLevels: number,
): Promise<{ vertices: number; faces: number; rows: InspectTiming[] }> {
  await initNode();
  let mesh = parseMesh(readFileSync(path, 'utf8'), formatFromFileName(path) ?? 'off');
  if (loopLevels > 0) mesh = subdivide(mesh, { scheme: 'loop', levels: loopLevels, triangulate: true });
  const rows: InspectTiming[] = [];
  const s = inspectMesh(mesh, { selfIntersections: true }).selfIntersections;
  if (s) rows.push({ computation: 'self-intersections', figure: s.pairs, ms: s.ms, skipped: false });
  const sphere = inspectMesh(mesh, { sphere: true }).sphere;
  if (sphere) rows.push({ computation: 'sphere', figure: sphere.radius, ms: sphere.ms, skipped: false });
  const hull = inspectMesh(mesh, { hull: true }).hull;
  if (hull) rows.push({ computation: 'hull', figure: hull.vertices, ms: hull.ms, skipped: false });
  const width = inspectMesh(mesh, { width: true }).width;
  if (width) rows.push({ computation: 'width', figure: width.width, ms: width.ms, skipped: width.skipped });
  return { vertices: mesh.positions.length / 3, faces: mesh.faceSizes.length, rows };
}
