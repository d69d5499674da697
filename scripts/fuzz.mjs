#!/usr/bin/env node
// Runs the libFuzzer targets of tests/fuzz (built by setup.mjs --fuzz into
// build/fuzz/) for N seconds each, two at a time (2 cores), and prints each
// target's executions and coverage (libFuzzer's cov: and ft:). Exits
// non-zero on a finding (crash, leak, UB, timeout, out-of-memory), printing
// the reproducer's path and the command that replays it.
//
// Seeds: tests/fixtures/ (and invalid/) copied at run time into
// build/fuzz/seeds/<target>/; libFuzzer adds what it finds to
// build/fuzz/corpus/<target>/, which later runs start from (--fresh empties
// it first). Findings go to build/fuzz/artifacts/<target>/.
// Usage: node scripts/fuzz.mjs [--seconds N] [--targets off,obj,...]
//                              [--jobs J] [--fresh]
import { spawn } from 'node:child_process';
import {
  copyFileSync,
  createWriteStream,
  existsSync,
  mkdirSync,
  readdirSync,
  readFileSync,
  rmSync,
  writeFileSync,
} from 'node:fs';
import { dirname, extname, join, relative, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const fuzzDir = join(root, 'build', 'fuzz');
const fixtures = join(root, 'tests', 'fixtures');
const dicts = join(root, 'tests', 'fuzz');

/**
 * Every target: its seeds (fixture extensions), whether its last byte is an
 * option byte (its seeds get one appended, so that a binary seed keeps its
 * size), its dictionary and its longest input.
 */
const TARGETS = {
  off: { seeds: ['.off'], dict: 'off.dict', maxLen: 8192 },
  obj: { seeds: ['.obj'], dict: 'obj.dict', maxLen: 8192 },
  ply: { seeds: ['.ply'], dict: 'ply.dict', maxLen: 8192 },
  stl: { seeds: ['.stl'], dict: 'stl.dict', maxLen: 8192 },
  build: { seeds: [], maxLen: 512 },
  schemes: { seeds: ['.off', '.obj', '.ply', '.stl'], optionByte: true, dict: 'off.dict', maxLen: 4096 },
  rules: { seeds: [], maxLen: 512 },
  writers: { seeds: ['.off', '.obj', '.ply', '.stl'], optionByte: true, dict: 'obj.dict', maxLen: 8192 },
};

function option(name, fallback) {
  const at = process.argv.indexOf(name);
  return at >= 0 ? process.argv[at + 1] : fallback;
}

const seconds = Number(option('--seconds', '60'));
const jobs = Number(option('--jobs', '2'));
const fresh = process.argv.includes('--fresh');
const names = option('--targets', Object.keys(TARGETS).join(',')).split(',');
for (const name of names) {
  if (!TARGETS[name]) {
    console.error(`[fuzz] unknown target '${name}'; targets: ${Object.keys(TARGETS).join(', ')}`);
    process.exit(2);
  }
}
if (!(seconds > 0) || !(jobs > 0)) {
  console.error('[fuzz] --seconds and --jobs take positive numbers');
  process.exit(2);
}
const program = join(fuzzDir, 'subdivlab_fuzz');
if (!existsSync(program)) {
  console.error('[fuzz] build/fuzz/subdivlab_fuzz is missing: run node scripts/setup.mjs --fuzz');
  process.exit(2);
}

/** Fixture files with one of `extensions`, in tests/fixtures and invalid/. */
function fixtureFiles(extensions) {
  return [fixtures, join(fixtures, 'invalid')].flatMap((dir) =>
    readdirSync(dir)
      .filter((f) => extensions.includes(extname(f)))
      .map((f) => join(dir, f)),
  );
}

function prepare(name) {
  const t = TARGETS[name];
  const seeds = join(fuzzDir, 'seeds', name);
  const corpus = join(fuzzDir, 'corpus', name);
  const artifacts = join(fuzzDir, 'artifacts', name);
  rmSync(seeds, { recursive: true, force: true });
  if (fresh) rmSync(corpus, { recursive: true, force: true });
  for (const dir of [seeds, corpus, artifacts]) mkdirSync(dir, { recursive: true });
  for (const file of fixtureFiles(t.seeds)) {
    const base = relative(fixtures, file).replaceAll('/', '-');
    if (t.optionByte) writeFileSync(join(seeds, base), Buffer.concat([readFileSync(file), Buffer.from([0])]));
    else copyFileSync(file, join(seeds, base));
  }
  const args = [
    corpus,
    seeds,
    `-max_total_time=${seconds}`,
    `-max_len=${t.maxLen}`,
    // A finding, not a slow machine: a small input taking seconds is a
    // quadratic loop; 2 GB is far above what the size caps let through.
    '-timeout=10',
    '-rss_limit_mb=2048',
    '-print_final_stats=1',
    `-artifact_prefix=${artifacts}/`,
  ];
  if (t.dict) args.push(`-dict=${join(dicts, t.dict)}`);
  return { corpus, args };
}

/** Runs one target; resolves to its figures parsed from libFuzzer's output. */
function runTarget(name) {
  const { args } = prepare(name);
  const logPath = join(fuzzDir, 'logs', `${name}.log`);
  mkdirSync(dirname(logPath), { recursive: true });
  const log = createWriteStream(logPath);
  const env = {
    ...process.env,
    ASAN_OPTIONS: 'detect_leaks=1:allocator_may_return_null=0',
    UBSAN_OPTIONS: 'print_stacktrace=1:halt_on_error=1',
  };
  const started = Date.now();
  return new Promise((resolve) => {
    const child = spawn(join(fuzzDir, `fuzz_${name}`), args, { cwd: fuzzDir, env });
    let text = '';
    const take = (chunk) => {
      log.write(chunk);
      text += chunk.toString();
      if (text.length > 1 << 20) text = text.slice(-(1 << 19));
    };
    child.stdout.on('data', take);
    child.stderr.on('data', take);
    child.on('close', (code) => {
      log.end();
      const last = (re) => [...text.matchAll(re)].at(-1)?.[1];
      resolve({
        name,
        code,
        seconds: (Date.now() - started) / 1000,
        execs: Number(last(/stat::number_of_executed_units:\s*(\d+)/g) ?? last(/^#(\d+)\s/gm) ?? 0),
        cov: Number(last(/cov: (\d+)/g) ?? 0),
        ft: Number(last(/ft: (\d+)/g) ?? 0),
        corpus: Number(last(/corp: (\d+)/g) ?? 0),
        artifact: last(/Test unit written to (\S+)/g),
        logPath,
        tail: text.split('\n').slice(-40).join('\n'),
      });
    });
  });
}

const results = [];
const queue = [...names];
async function worker() {
  while (queue.length > 0) {
    const name = queue.shift();
    const r = await runTarget(name);
    results.push(r);
    const status = r.code === 0 ? 'ok' : `FINDING (exit ${r.code})`;
    console.log(
      `[fuzz] ${name.padEnd(8)} ${String(r.execs).padStart(10)} execs in ${r.seconds.toFixed(0)} s` +
        `  cov ${r.cov}  ft ${r.ft}  corpus ${r.corpus}  ${status}`,
    );
    if (r.code !== 0) {
      console.log(r.tail);
      console.log(`[fuzz] log: ${relative(root, r.logPath)}`);
      if (r.artifact) {
        const path = relative(root, resolve(fuzzDir, r.artifact));
        console.log(`[fuzz] reproducer: ${path}`);
        console.log(`[fuzz] replay: build/fuzz/fuzz_${name} ${path}`);
      }
    }
  }
}
const started = Date.now();
await Promise.all(Array.from({ length: Math.min(jobs, names.length) }, worker));
const total = results.reduce((sum, r) => sum + r.execs, 0);
const failed = results.filter((r) => r.code !== 0);
console.log(
  `[fuzz] ${results.length} targets, ${total} executions in ${((Date.now() - started) / 1000).toFixed(0)} s, ` +
    `${failed.length} with findings`,
);
process.exit(failed.length > 0 ? 1 : 0);
