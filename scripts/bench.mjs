#!/usr/bin/env node
// `npm run bench` (after setup.mjs): one level of each scheme on a real mesh
// of about 100k faces, natively (build/native/subdiv_bench_native, from
// wasm/bench/bench_native.cpp) and in Node through the WASM module
// (build/cli/bench-wasm.mjs), from the same C++ core, and for Loop and
// Catmull-Clark with OpenSubdiv's Far layer (subdiv_bench_osd, from
// wasm/bench/bench_osd.cpp and Debian's libosd-dev). Prints the median of
// RUNS timed runs (after one warm-up), ns per output face, and the WASM time
// as a ratio to native CGAL and to OpenSubdiv, then parse and write MB/s of
// OFF and OBJ in Node through the WASM module (bunny00, CGAL's
// refined_elephant and bunny00 after two Loop steps), and writes
// build/bench.json.
// Usage: node scripts/bench.mjs [MESH.off] [--runs N] [--io-only]
import { spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { cpus } from 'node:os';
import { basename, dirname, join } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const SCHEMES = ['catmull-clark', 'loop', 'doo-sabin', 'sqrt3'];

const argv = process.argv.slice(2);
const ioOnlyAt = argv.indexOf('--io-only');
const ioOnly = ioOnlyAt >= 0;
if (ioOnly) argv.splice(ioOnlyAt, 1);
const runsAt = argv.indexOf('--runs');
const runs = runsAt >= 0 ? Number(argv.splice(runsAt, 2)[1]) : 5;
const meshPath = argv[0] ?? join(root, 'public', 'meshes', 'cgal', 'bunny00.off');
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
const { benchWasm, benchIo } = await import(pathToFileURL(wasmBundle).href);

/** One level of each scheme: WASM against native CGAL and OpenSubdiv. */
async function benchSchemes() {
  // The native benchmark, built Release in build/native like the tests.
  const buildDir = join(root, 'build', 'native');
  if (!existsSync(join(buildDir, 'CMakeCache.txt'))) {
    run('cmake', ['-S', 'wasm', '-B', buildDir, '-DCMAKE_BUILD_TYPE=Release']);
  }
  console.log('[bench] building subdiv_bench_native and subdiv_bench_osd (Release)');
  run('cmake', ['--build', buildDir, '--parallel', '2', '--target', 'subdiv_bench_native']);
  const osdBench = join(buildDir, 'subdiv_bench_osd');
  const OSD_SCHEMES = ['catmull-clark', 'loop'];
  const hasOsd =
    spawnSync('cmake', ['--build', buildDir, '--parallel', '2', '--target', 'subdiv_bench_osd'], { cwd: root })
      .status === 0 && existsSync(osdBench);
  if (!hasOsd) console.log('[bench] OpenSubdiv (libosd-dev) not found: no OpenSubdiv column');

  const counts = /OFF\s+(\d+)\s+(\d+)/.exec(readFileSync(meshPath, 'utf8').slice(0, 4096));
  const size = counts ? ` (${counts[1]} vertices, ${counts[2]} faces)` : '';
  console.log(`[bench] ${basename(meshPath)}${size}, ${runs} timed runs per scheme`);

  // Scheme by scheme, native then WASM, so that a change in the machine's load
  // during the run affects both sides of a ratio alike.
  const native = [];
  const wasm = [];
  const osd = [];
  for (const scheme of SCHEMES) {
    const withOsd = hasOsd && OSD_SCHEMES.includes(scheme);
    console.log(`[bench] ${scheme}: native, ${withOsd ? 'OpenSubdiv, ' : ''}then WASM in Node`);
    native.push(JSON.parse(run(join(buildDir, 'subdiv_bench_native'), [meshPath, String(runs), scheme]).trim()));
    if (withOsd) osd.push(JSON.parse(run(osdBench, [meshPath, String(runs), '1', scheme]).trim()));
    wasm.push(...(await benchWasm(meshPath, runs, [scheme])));
  }

  const rows = SCHEMES.map((scheme) => {
    const n = native.find((r) => r.scheme === scheme);
    const w = wasm.find((r) => r.scheme === scheme);
    const o = osd.find((r) => r.scheme === scheme);
    for (const [who, r] of [
      ['WASM', w],
      ['OpenSubdiv', o],
    ]) {
      if (r && r.faces !== n.faces) {
        console.error(`error: ${scheme}: native gives ${n.faces} faces, ${who} ${r.faces}`);
        process.exit(1);
      }
    }
    return {
      scheme,
      faces: n.faces,
      wasm_ms: w.median_ms,
      wasm_ns_per_face: (w.median_ms * 1e6) / n.faces,
      native_ms: n.median_ms,
      osd_ms: o?.median_ms ?? null,
      ratio: w.median_ms / n.median_ms,
      ratio_osd: o ? w.median_ms / o.median_ms : null,
    };
  });

  const num = (x, n) => (x === null ? '–' : x.toFixed(n)).padStart(11);
  const head = ['faces out', 'WASM ms', 'ns/face', 'CGAL ms', 'OSD ms', 'WASM/CGAL', 'WASM/OSD'];
  console.log(`\n${pad('scheme', 15)}${head.map((h) => h.padStart(11)).join('')}`);
  for (const r of rows) {
    console.log(
      `${pad(r.scheme, 15)}${String(r.faces).padStart(11)}${num(r.wasm_ms, 1)}${num(r.wasm_ns_per_face, 0)}` +
        `${num(r.native_ms, 1)}${num(r.osd_ms, 1)}${num(r.ratio, 2)}${num(r.ratio_osd, 2)}`,
    );
  }
  return { rows, native, wasm, osd };
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
const schemes = ioOnly ? { rows: [], native: [], wasm: [], osd: [] } : await benchSchemes();
const io = await benchInputOutput();
const machine = `${cpus()[0]?.model ?? 'unknown CPU'}, ${cpus().length} cores, Node ${process.version}`;
console.log(`\n(median of ${runs} runs after one warm-up; ${machine})`);

mkdirSync(join(root, 'build'), { recursive: true });
writeFileSync(
  join(root, 'build', 'bench.json'),
  `${JSON.stringify({ mesh: basename(meshPath), runs, machine, ...schemes, io }, null, 2)}\n`,
);
