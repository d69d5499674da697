#!/usr/bin/env node
// Every test, in order, after `node scripts/setup.mjs` (npm test runs both):
//   1. lint        biome check + tsc --noEmit + clang-format --check
//   2. native      build/native/core_tests and osd_tests (GoogleTest; built by
//                  setup.mjs --native; osd_tests compares creasing with OpenSubdiv)
//   3. wasm32      the same tests built with em++, run by Node
//                  (build/wasm/core_tests_wasm.cjs; setup.mjs --wasm-tests)
//   4. fuzz        the libFuzzer targets of tests/fuzz (clang, ASan + UBSan;
//                  setup.mjs --fuzz), each for a few seconds from the
//                  fixtures (scripts/fuzz.mjs); a finding fails the step
//   5. unit        vitest (tests/unit, Node against the real WASM and the CLI)
//   6. e2e         Playwright (tests/e2e), when playwright.config.ts exists
// Each step's output is shown; the first failing step stops the run with a
// non-zero exit. The last line sums the tests: "N passed, M failed".
// Usage: node scripts/test.mjs [--skip lint,native,wasm32,fuzz,unit,e2e] (for local runs)
import { spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, rmSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const bin = (name) => join(root, 'node_modules', '.bin', name);
const resultsDir = join(root, 'build', 'test-results');
mkdirSync(resultsDir, { recursive: true });

const totals = { passed: 0, failed: 0 };
const skipAt = process.argv.indexOf('--skip');
const skipped = new Set(skipAt >= 0 ? (process.argv[skipAt + 1] ?? '').split(',') : []);

function run(cmd, args, options = {}) {
  const result = spawnSync(cmd, args, { stdio: 'inherit', cwd: root, ...options });
  return result.status ?? 1;
}

/** Adds a suite's counts; a failing step that reported no failed test counts as one failure. */
function count(status, passed, failed) {
  totals.passed += passed;
  totals.failed += status !== 0 && failed === 0 ? 1 : failed;
}

function heading(title) {
  console.log(`\n=== ${title} ===`);
}

function finish(failedStep) {
  if (failedStep) console.error(`\n[test] step "${failedStep}" failed`);
  console.log(`${totals.passed} passed, ${totals.failed} failed`);
  process.exit(failedStep ? 1 : 0);
}

function readJson(path) {
  try {
    return JSON.parse(readFileSync(path, 'utf8'));
  } catch {
    return null;
  }
}

function lint() {
  heading('lint: biome check');
  if (run(bin('biome'), ['check', '.']) !== 0) return false;
  heading('lint: tsc --noEmit');
  if (run(bin('tsc'), ['--noEmit', '-p', '.']) !== 0) return false;
  heading('lint: clang-format --check');
  return run(process.execPath, [join(root, 'scripts', 'clang-format.mjs'), '--check']) === 0;
}

/** Runs a GoogleTest program (`cmd args…`) and counts its XML report, `report`.xml. */
function googleTest(report, cmd, args) {
  const xml = join(resultsDir, `${report}.xml`);
  rmSync(xml, { force: true });
  const status = run(cmd, [...args, `--gtest_output=xml:${xml}`]);
  if (existsSync(xml)) {
    const head = /<testsuites[^>]*>/.exec(readFileSync(xml, 'utf8'))?.[0] ?? '';
    const attr = (name) => Number(new RegExp(`\\b${name}="(\\d+)"`).exec(head)?.[1] ?? 0);
    const failed = attr('failures') + attr('errors');
    count(status, attr('tests') - failed - attr('disabled') - attr('skipped'), failed);
  } else {
    count(status, 0, 0);
  }
  return status === 0;
}

function nativeTests() {
  heading('native: build (setup.mjs --native)');
  if (run(process.execPath, [join(root, 'scripts', 'setup.mjs'), '--native']) !== 0) return false;
  heading('native: core_tests');
  const core = googleTest('core_tests', join(root, 'build', 'native', 'core_tests'), []);
  // Creasing against OpenSubdiv (Debian's libosd-dev, which set-up installs).
  heading('native: osd_tests');
  const osd = join(root, 'build', 'native', 'osd_tests');
  if (!existsSync(osd)) {
    console.error('osd_tests was not built: is libosd-dev installed (node scripts/setup.mjs)?');
    count(1, 0, 1);
    return false;
  }
  return googleTest('osd_tests', osd, []) && core;
}

/** tests/core again as wasm32 (32-bit size_t and pointers, dlmalloc), under Node. */
function wasm32Tests() {
  heading('wasm32: build (setup.mjs --wasm-tests)');
  if (run(process.execPath, [join(root, 'scripts', 'setup.mjs'), '--wasm-tests']) !== 0) return false;
  heading('wasm32: core_tests_wasm (Node)');
  return googleTest('core_tests_wasm', process.execPath, [join(root, 'build', 'wasm', 'core_tests_wasm.cjs')]);
}

/**
 * Seconds each fuzz target runs in npm test: the step (build and run) must
 * stay within about 2.5 of CI's 20 minutes (README, Fuzzing).
 */
const FUZZ_SECONDS = 6;

/** The fuzz targets' short pass: every target, FUZZ_SECONDS each, two at a time. */
function fuzzTests() {
  heading('fuzz: build (setup.mjs --fuzz)');
  if (run(process.execPath, [join(root, 'scripts', 'setup.mjs'), '--fuzz']) !== 0) return false;
  heading(`fuzz: every target for ${FUZZ_SECONDS} s`);
  const script = join(root, 'scripts', 'fuzz.mjs');
  const status = run(process.execPath, [script, '--seconds', String(FUZZ_SECONDS), '--fresh']);
  count(status, status === 0 ? 1 : 0, 0);
  return status === 0;
}

function unitTests() {
  heading('unit: vitest');
  const json = join(resultsDir, 'vitest.json');
  rmSync(json, { force: true });
  const status = run(bin('vitest'), ['run', '--reporter=default', '--reporter=json', `--outputFile.json=${json}`]);
  const report = readJson(json);
  count(status, report?.numPassedTests ?? 0, report?.numFailedTests ?? 0);
  return status === 0;
}

function e2eTests() {
  if (!existsSync(join(root, 'playwright.config.ts'))) {
    heading('e2e: skipped (no playwright.config.ts)');
    return true;
  }
  heading('e2e: playwright');
  const json = join(resultsDir, 'playwright.json');
  rmSync(json, { force: true });
  const env = { ...process.env, PLAYWRIGHT_JSON_OUTPUT_NAME: json };
  const status = run(bin('playwright'), ['test', '--reporter=list,json'], { env });
  const stats = readJson(json)?.stats;
  count(status, stats ? stats.expected + stats.flaky : 0, stats?.unexpected ?? 0);
  return status === 0;
}

const steps = [
  ['lint', lint],
  ['native', nativeTests],
  ['wasm32', wasm32Tests],
  ['fuzz', fuzzTests],
  ['unit', unitTests],
  ['e2e', e2eTests],
];
for (const [name, step] of steps) {
  if (skipped.has(name)) {
    heading(`${name}: skipped (--skip)`);
    continue;
  }
  const start = Date.now();
  const passed = step();
  // CI allows 20 minutes for everything: each step says what it took.
  console.log(`[test] step "${name}" took ${Math.round((Date.now() - start) / 1000)} s`);
  if (!passed) finish(name);
}
finish(null);
