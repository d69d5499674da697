#!/usr/bin/env node
// `npm run bench` (after setup.mjs). Subdivision: one level of each scheme
// on bunny00 (75k faces; quad-triangle two levels too), then Catmull-Clark
// and Loop to 1-5 M faces (see
// schemeRows), each natively with CGAL's own hosts
// (build/native/subdiv_bench_native, from wasm/bench/bench_native.cpp), for
// Catmull-Clark and Loop with OpenSubdiv's Far layer (subdiv_bench_osd, from
// wasm/bench/bench_osd.cpp and Debian's libosd-dev), and in Node through the
// WASM module (build/cli/bench-wasm.mjs: the product's path, the fast hosts
// where a scheme has one). Prints the median of RUNS timed runs (after one
// warm-up), ns and predicted peak bytes per output face, and the WASM time
// as a ratio to native CGAL and to OpenSubdiv. Then parse and write MB/s of
// OFF and OBJ in Node through the WASM module (bunny00, CGAL's
// refined_elephant and bunny00 after two Loop steps). Then the app's time to
// screen in Chromium (scripts/bench-app.mjs). Writes build/bench.json.
// Then Inspect's computations natively and in WASM (benchInspectTable).
// Usage: node scripts/bench.mjs [MESH.off] [--runs N] [--io-only | --app-only | --inspect-only]
import { spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, writeFileSync } from 'node:fs';
import { cpus } from 'node:os';
import { basename, dirname, join } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { benchApp, printApp } from './bench-app.mjs';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const SCHEMES = ['catmull-clark', 'loop', 'doo-sabin', 'sqrt3', 'quad-triangle'];
const OSD_SCHEMES = ['catmull-clark', 'loop'];
/** The custom scheme with the rules panel's presets (public/rules/NAME.json), one on each host. */
const CUSTOM_SCHEMES = ['custom:catmull-clark', 'custom:loop', 'custom:doo-sabin', 'custom:sqrt3'];

const argv = process.argv.slice(2);
/** Takes `flag` out of argv; true when it was there. */
function takeFlag(flag) {
  const at = argv.indexOf(flag);
  if (at >= 0) argv.splice(at, 1);
  return at >= 0;
}
const ioOnly = takeFlag('--io-only');
const appOnly = takeFlag('--app-only');
const inspectOnly = takeFlag('--inspect-only');
const runsAt = argv.indexOf('--runs');
const runs = runsAt >= 0 ? Number(argv.splice(runsAt, 2)[1]) : 5;
const defaultMesh = join(root, 'public', 'meshes', 'cgal', 'bunny00.off');
const meshPath = argv[0] ?? defaultMesh;
if (!existsSync(meshPath)) {
  console.error(`error: ${meshPath} not found; run node scripts/setup.mjs (it extracts CGAL's bunny00.off)`);
  process.exit(1);
}

function run(cmd, args) {
  const r = spawnSync(cmd, args, { cwd: root, stdio: ['ignore', 'pipe', 'inherit'], encoding: 'utf8' });
  if (r.status !== 0) {
    console.error(`error: ${cmd} ${args.join(' ')} failed with status ${r.status}`);
    process.exit(1);
  }
  return r.stdout;
}

const wasmBundle = join(root, 'build', 'cli', 'bench-wasm.mjs');
if (!existsSync(wasmBundle)) {
  console.error('error: build/cli/bench-wasm.mjs missing; run node scripts/setup.mjs');
  process.exit(1);
}
const { benchWasm, benchIo, benchInspect } = await import(pathToFileURL(wasmBundle).href);

/**
 * The rows: one level of each scheme on the bench mesh, then two levels of
 * quad-triangle and Doo-Sabin, then Catmull-Clark and Loop to 1-5 M faces
 * (two levels of bunny00 and of CGAL's refined_elephant, one level of a
 * 1.2 M-face input), then two of custom rules on each host, where the fast
 * hosts' targets are set.
 */
function schemeRows() {
  const rows = SCHEMES.map((scheme) => ({ mesh: meshPath, scheme, levels: 1, runs }));
  if (meshPath !== defaultMesh) return rows;
  const big = Math.min(runs, 3);
  const elephant = cgalDataMesh('refined_elephant.off');
  const million = loopInput(defaultMesh, 2, 'bunny00-loop2.off');
  rows.push({ mesh: defaultMesh, scheme: 'quad-triangle', levels: 2, runs: big });
  // Doo-Sabin to about 1 M faces (its target counts there): bunny00 x2,
  // refined_elephant x2.
  for (const mesh of [defaultMesh, elephant]) {
    if (mesh) rows.push({ mesh, scheme: 'doo-sabin', levels: 2, runs: big });
  }
  for (const [mesh, levels] of [
    [defaultMesh, 2],
    [elephant, 2],
    [million, 1],
  ]) {
    if (!mesh) continue;
    for (const scheme of OSD_SCHEMES) rows.push({ mesh, scheme, levels, runs: big });
  }
  // Custom rules on the four hosts, to 0.7-1.2 M faces (their target counts there).
  for (const scheme of CUSTOM_SCHEMES) rows.push({ mesh: defaultMesh, scheme, levels: 2, runs: big });
  return rows;
}

/** `path` after `levels` Loop steps, written by the CLI into build/meshes/ (a large input). */
function loopInput(path, levels, name) {
  const out = join(root, 'build', 'meshes', name);
  if (!existsSync(out)) {
    mkdirSync(dirname(out), { recursive: true });
    run(process.execPath, [
      join(root, 'bin', 'subdiv.mjs'),
      path,
      '--scheme',
      'loop',
      '--levels',
      String(levels),
      '-o',
      out,
    ]);
  }
  return out;
}

/** Each row: WASM against native CGAL (its own hosts) and OpenSubdiv. */
async function benchSchemes() {
  // The native benchmark, built Release in build/native like the tests.
  const buildDir = join(root, 'build', 'native');
  if (!existsSync(join(buildDir, 'CMakeCache.txt'))) {
    run('cmake', ['-S', 'wasm', '-B', buildDir, '-DCMAKE_BUILD_TYPE=Release']);
  }
  console.log('[bench] building subdiv_bench_native and subdiv_bench_osd (Release)');
  run('cmake', ['--build', buildDir, '--parallel', '2', '--target', 'subdiv_bench_native']);
  const osdBench = join(buildDir, 'subdiv_bench_osd');
  const hasOsd =
    spawnSync('cmake', ['--build', buildDir, '--parallel', '2', '--target', 'subdiv_bench_osd'], { cwd: root })
      .status === 0 && existsSync(osdBench);
  if (!hasOsd) console.log('[bench] OpenSubdiv (libosd-dev) not found: no OpenSubdiv column');

  // Row by row, native then WASM, so that a change in the machine's load
  // during the run affects both sides of a ratio alike.
  const rows = [];
  const raw = [];
  for (const row of schemeRows()) {
    const name = `${basename(row.mesh, '.off')} x${row.levels}`;
    const withOsd = hasOsd && OSD_SCHEMES.includes(row.scheme);
    console.log(`[bench] ${row.scheme}, ${name}: native CGAL, ${withOsd ? 'OpenSubdiv, ' : ''}then WASM in Node`);
    const args = [row.mesh, String(row.runs), String(row.levels), row.scheme];
    const n = JSON.parse(run(join(buildDir, 'subdiv_bench_native'), args).trim());
    const o = withOsd ? JSON.parse(run(osdBench, args).trim()) : null;
    const [w] = await benchWasm(
      row.mesh,
      row.runs,
      [row.scheme],
      row.levels,
      join(root, 'public', 'rules'),
      Math.min(row.runs, 3),
    );
    for (const [who, r] of [
      ['WASM', w],
      ['OpenSubdiv', o],
    ]) {
      if (r && r.faces !== n.faces) {
        console.error(`error: ${row.scheme} on ${name}: native gives ${n.faces} faces, ${who} ${r.faces}`);
        process.exit(1);
      }
    }
    raw.push({ ...row, native: n, osd: o, wasm: w });
    rows.push({
      mesh: name,
      scheme: row.scheme,
      faces: n.faces,
      wasm_ms: w.median_ms,
      wasm_ns_per_face: (w.median_ms * 1e6) / n.faces,
      peak_bytes_per_face: w.peak_bytes / n.faces,
      native_ms: n.median_ms,
      osd_ms: o?.median_ms ?? null,
      ratio: w.median_ms / n.median_ms,
      ratio_osd: o ? w.median_ms / o.median_ms : null,
      before_ms: w.cgal_hosts.median_ms,
      before_bytes_per_face: w.cgal_hosts.peak_bytes / n.faces,
    });
  }

  const num = (x, n) => (x === null ? '–' : x.toFixed(n)).padStart(10);
  const head = [
    'faces out',
    'WASM ms',
    'ns/face',
    'B/face',
    'CGAL ms',
    'OSD ms',
    '/CGAL',
    '/OSD',
    'before ms',
    'B/face',
  ];
  console.log(`\n${pad('scheme', 22)}${pad('mesh', 22)}${head.map((h) => h.padStart(10)).join('')}`);
  for (const r of rows) {
    console.log(
      `${pad(r.scheme, 22)}${pad(r.mesh, 22)}${String(r.faces).padStart(10)}${num(r.wasm_ms, 1)}` +
        `${num(r.wasm_ns_per_face, 0)}${num(r.peak_bytes_per_face, 0)}${num(r.native_ms, 1)}${num(r.osd_ms, 1)}` +
        `${num(r.ratio, 2)}${num(r.ratio_osd, 2)}${num(r.before_ms, 1)}${num(r.before_bytes_per_face, 0)}`,
    );
  }
  console.log(
    "(WASM: subdivide() in Node, copies in and out included; B/face: the peak the memory model predicts, which bounds the measured one; CGAL: native, its own hosts; /CGAL, /OSD: WASM time over theirs; before: the same call on CGAL's hosts in WASM (option cgalHosts), as the product ran before its fast hosts, and its B/face)",
  );
  return { rows, raw };
}

/** A mesh of CGAL's data set (libcgal-demo) not kept in public/: extracted into build/meshes/. */
function cgalDataMesh(name) {
  const path = join(root, 'build', 'meshes', name);
  if (existsSync(path)) return path;
  const archive = ['/usr/share/doc/libcgal-demo/data.tar.gz', '/usr/share/doc/libcgal-dev/data.tar.gz'].find((p) =>
    existsSync(p),
  );
  if (!archive) return null;
  mkdirSync(dirname(path), { recursive: true });
  run('tar', ['-xzf', archive, '-C', dirname(path), '--strip-components=2', `data/meshes/${name}`]);
  return existsSync(path) ? path : null;
}

/**
 * Inspect's computations (CGAL's self-intersection test, smallest enclosing
 * sphere, convex hull, minimum width), each alone, on CGAL's larger meshes
 * and their Loop level 2, natively (subdiv_bench_inspect) and in the WASM
 * core: the tutorial's table, with the ratio. The figures must agree.
 */
function benchInspectTable() {
  const buildDir = join(root, 'build', 'native');
  console.log('[bench] building subdiv_bench_inspect (Release)');
  run('cmake', ['--build', buildDir, '--parallel', '2', '--target', 'subdiv_bench_inspect']);
  const data = join(root, 'public', 'meshes', 'cgal');
  const cases = [
    ['elephant.off', 0],
    ['elephant.off', 2],
    ['mannequin-devil.off', 0],
    ['mannequin-devil.off', 2],
    ['bunny00.off', 0],
  ].filter(([name]) => existsSync(join(data, name)));
  return (async () => {
    const rows = [];
    for (const [name, levels] of cases) {
      const path = join(data, name);
      const label = `${basename(name, '.off')}${levels ? `, Loop x${levels}` : ''}`;
      console.log(`[bench] inspect ${label}: native, then WASM in Node`);
      const n = JSON.parse(run(join(buildDir, 'subdiv_bench_inspect'), [path, String(levels)]).trim());
      const w = await benchInspect(path, levels);
      for (const [k, nr] of n.rows.entries()) {
        const wr = w.rows[k];
        const same =
          nr.skipped === wr.skipped && Math.abs(nr.figure - wr.figure) <= 1e-12 * Math.max(1, Math.abs(nr.figure));
        if (!same) {
          console.error(`error: ${nr.computation} on ${label}: native gives ${nr.figure}, WASM ${wr.figure}`);
          process.exit(1);
        }
        rows.push({
          mesh: label,
          faces: n.faces,
          computation: nr.computation,
          figure: nr.figure,
          skipped: nr.skipped,
          native_ms: nr.ms,
          wasm_ms: wr.ms,
          ratio: nr.skipped ? null : wr.ms / nr.ms,
        });
      }
    }
    const num = (x, n) => (x === null ? '–' : x.toFixed(n)).padStart(11);
    console.log(
      `\n${pad('mesh', 26)}${'faces'.padStart(9)}  ${pad('computation', 20)}${['figure', 'native ms', 'WASM ms', 'WASM/nat'].map((h) => h.padStart(11)).join('')}`,
    );
    for (const r of rows) {
      const figure = r.skipped ? 'skipped' : Number.isInteger(r.figure) ? String(r.figure) : r.figure.toPrecision(6);
      console.log(
        `${pad(r.mesh, 26)}${String(r.faces).padStart(9)}  ${pad(r.computation, 20)}${figure.padStart(11)}` +
          `${num(r.skipped ? null : r.native_ms, 1)}${num(r.skipped ? null : r.wasm_ms, 1)}${num(r.ratio, 2)}`,
      );
    }
    console.log(
      "(figure: crossing face pairs, sphere radius, hull vertices, width; each computation alone, one run, the core's own time; width skipped above 4000 hull vertices)",
    );
    return rows;
  })();
}

/** Parse and write MB/s of OFF and OBJ through the WASM module. */
async function benchInputOutput() {
  const bunny = join(root, 'public', 'meshes', 'cgal', 'bunny00.off');
  const elephant = cgalDataMesh('refined_elephant.off');
  const sources = [
    { name: basename(meshPath, '.off'), path: meshPath },
    ...(elephant ? [{ name: 'refined_elephant', path: elephant }] : []),
    ...(existsSync(bunny) ? [{ name: 'bunny00, Loop x2', path: bunny, loopLevels: 2 }] : []),
  ];
  console.log(`[bench] parse and write: ${sources.map((s) => s.name).join('; ')}`);
  const io = await benchIo(sources, runs);
  const mb = (x) => x.toFixed(1).padStart(10);
  console.log(
    `\n${pad('mesh', 20)}${pad('format', 7)}${['MB', 'parse ms', 'parse MB/s', 'write ms', 'write MB/s'].map((h) => h.padStart(11)).join('')}`,
  );
  for (const r of io) {
    console.log(
      `${pad(r.mesh, 20)}${pad(r.format, 7)}${mb(r.bytes / 1e6)} ${mb(r.parse_ms)} ${mb(r.parse_mb_s)} ${mb(r.write_ms)} ${mb(r.write_mb_s)}`,
    );
  }
  console.log(
    '(parse: parseMesh(text) from a JS string, checks included; write: exportMeshChunks, the pieces an export saves)',
  );
  return io;
}

const pad = (s, n) => String(s).padEnd(n);
const schemes = ioOnly || appOnly || inspectOnly ? { rows: [], raw: [] } : await benchSchemes();
const io = appOnly || inspectOnly ? [] : await benchInputOutput();
const inspect = ioOnly || appOnly ? [] : await benchInspectTable();
const machine = `${cpus()[0]?.model ?? 'unknown CPU'}, ${cpus().length} cores, Node ${process.version}`;
if (!appOnly && !inspectOnly) console.log(`\n(median of ${runs} runs after one warm-up; ${machine})`);
// A page load and two steps per run: at most three.
const appRuns = Math.min(runs, 3);
const appMeshes = { refined_elephant: cgalDataMesh('refined_elephant.off') };
const app = ioOnly || inspectOnly ? [] : await benchApp(appRuns, appMeshes);
if (app.length > 0) printApp(app, appRuns);

mkdirSync(join(root, 'build'), { recursive: true });
writeFileSync(
  join(root, 'build', 'bench.json'),
  `${JSON.stringify({ mesh: basename(meshPath), runs, machine, ...schemes, io, inspect, app }, null, 2)}\n`,
);
