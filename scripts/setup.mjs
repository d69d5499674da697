#!/usr/bin/env node
// Everything `npm start` and `npm test` need on a fresh Debian/Ubuntu machine,
// each step skipped when already done:
//   1. Debian packages (through sudo when not root)
//   2. npm dependencies
//   3. CGAL's sample meshes extracted from Debian's data set into public/
//   4. the WASM module (CMake + Emscripten; rebuilt only when sources changed)
//   5. the native core and its tests (with --native)
//   6. tests/core as a wasm32 program for Node (with --wasm-tests)
//   7. with --fuzz, only the Debian packages and the libFuzzer targets of
//      tests/fuzz (clang 14, ASan + UBSan) in build/fuzz/, for scripts/fuzz.mjs
// CMake builds use 2 jobs; CMAKE_BUILD_PARALLEL_LEVEL sets another number.
// Usage: node scripts/setup.mjs [--wasm-only] [--native] [--wasm-tests] | --fuzz
import { spawnSync } from 'node:child_process';
import { existsSync, lstatSync, mkdirSync, readFileSync, statSync, symlinkSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const args = new Set(process.argv.slice(2));
const jobs = process.env.CMAKE_BUILD_PARALLEL_LEVEL || '2';

const DEBIAN_PACKAGES = [
  'emscripten',
  'libcgal-dev',
  'libboost-dev',
  'libgtest-dev',
  'cmake',
  'g++',
  'make',
  'chromium',
  'libcgal-demo',
  'clang-format',
  'libosd-dev',
  'libfast-float-dev',
  // The figure tests render the PDF and EPS exports: pdftoppm and pdfinfo (poppler), gs (ghostscript).
  'poppler-utils',
  'ghostscript',
  // The fuzz targets (tests/fuzz): clang 14 and its libFuzzer and sanitizer
  // runtimes (libclang_rt.fuzzer-x86_64.a), and llvm-symbolizer for their
  // stack traces.
  'clang-14',
  'libclang-rt-14-dev',
  'llvm-14',
];

function log(message) {
  console.log(`[setup] ${message}`);
}

function run(cmd, cmdArgs, options = {}) {
  const result = spawnSync(cmd, cmdArgs, { stdio: 'inherit', cwd: root, ...options });
  if (result.status !== 0) {
    throw new Error(`${cmd} ${cmdArgs.join(' ')} failed with status ${result.status}`);
  }
}

function missingDebianPackages() {
  return DEBIAN_PACKAGES.filter((name) => {
    // biome-ignore lint/suspicious/noTemplateCurlyInString: dpkg-query's own format syntax
    const r = spawnSync('dpkg-query', ['-W', '-f=${Status}', name], { encoding: 'utf8' });
    return r.status !== 0 || !r.stdout.includes('install ok installed');
  });
}

function installDebianPackages() {
  const missing = missingDebianPackages();
  if (missing.length === 0) return;
  const asRoot = process.getuid?.() === 0;
  log(`installing Debian packages: ${missing.join(' ')}`);
  const env = { ...process.env, DEBIAN_FRONTEND: 'noninteractive' };
  const apt = (aptArgs) =>
    asRoot ? run('apt-get', aptArgs, { env }) : run('sudo', ['-E', 'apt-get', ...aptArgs], { env });
  apt(['update', '-q']);
  // With recommends: Chromium's fonts and GL libraries come that way.
  apt(['install', '-y', '-q', ...missing]);
}

function installNpmDependencies() {
  const stamp = join(root, 'node_modules', '.package-lock.json');
  const lock = join(root, 'package-lock.json');
  if (existsSync(stamp) && statSync(stamp).mtimeMs >= statSync(lock).mtimeMs) return;
  log('installing npm dependencies');
  // Exactly the locked versions. The lock file names Biome's binaries for
  // every platform (npm ci refuses one that lacks them); those of other
  // platforms have no integrity hash there, as the registry this project is
  // built from serves only Linux's, and are never fetched on Linux.
  run('npm', ['ci', '--no-audit', '--no-fund']);
}

function extractCgalMeshes() {
  const names = [
    'mannequin-devil.off',
    'elephant.off',
    'bunny00.off',
    'fandisk.off',
    'cube_quad.off',
    'holes.off',
    'torus_quad.off',
  ];
  const outDir = join(root, 'public', 'meshes', 'cgal');
  if (names.every((n) => existsSync(join(outDir, n)))) return;
  const archive = ['/usr/share/doc/libcgal-demo/data.tar.gz', '/usr/share/doc/libcgal-dev/data.tar.gz'].find((p) =>
    existsSync(p),
  );
  if (!archive) throw new Error('CGAL data set not found: install Debian package libcgal-demo');
  log(`extracting CGAL sample meshes from ${archive}`);
  mkdirSync(outDir, { recursive: true });
  run('tar', ['-xzf', archive, '-C', outDir, '--strip-components=2', ...names.map((n) => `data/meshes/${n}`)]);
}

function cmakeBuild(buildDir, configure, targets = []) {
  if (!existsSync(join(buildDir, 'CMakeCache.txt'))) {
    mkdirSync(buildDir, { recursive: true });
    run(configure[0], configure.slice(1));
  }
  run('cmake', ['--build', buildDir, '--parallel', jobs, ...(targets.length > 0 ? ['--target', ...targets] : [])]);
}

const wasmBuildDir = join(root, 'build', 'wasm');
// Debian's emcc runs its JS optimizer with the system node modules (acorn).
const emccEnv = { ...process.env, NODE_PATH: '/usr/share/nodejs' };

function buildWasm() {
  const configure = ['emcmake', 'cmake', '-S', 'wasm', '-B', wasmBuildDir, '-DCMAKE_BUILD_TYPE=Release'];
  if (!existsSync(join(wasmBuildDir, 'CMakeCache.txt'))) {
    mkdirSync(wasmBuildDir, { recursive: true });
    run(configure[0], configure.slice(1), { env: emccEnv });
  }
  log('building the WASM module (no-op when sources are unchanged)');
  run('cmake', ['--build', wasmBuildDir, '--parallel', jobs], { env: emccEnv });
}

/**
 * web/core/generated/scheme-table.json: the core's scheme and host table
 * (wasm/src/core/scheme_table.cpp) as the built module answers it, so that
 * the app reads the names, labels, descriptions and needs of the schemes
 * before its worker has started. Rewritten only when it changed.
 */
async function writeSchemeTable() {
  const generated = join(root, 'web', 'core', 'generated');
  const { default: createModule } = await import(pathToFileURL(join(generated, 'subdivlab.mjs')).href);
  const core = await createModule({
    wasmBinary: readFileSync(join(generated, 'subdivlab.wasm')),
    print: () => {},
    printErr: () => {},
  });
  const info = core.scheme_info();
  if (!info.ok) throw new Error(`the core's scheme table: ${info.message}`);
  const text = `${JSON.stringify({ hosts: info.hosts, schemes: info.schemes }, null, 2)}\n`;
  const path = join(generated, 'scheme-table.json');
  if (!existsSync(path) || readFileSync(path, 'utf8') !== text) {
    log('writing the scheme table for the app (web/core/generated/scheme-table.json)');
    writeFileSync(path, text);
  }
}

/** build/wasm/core_tests_wasm.cjs: tests/core on the module's core objects. */
function buildWasmTests() {
  log('building the wasm32 core tests (no-op when sources are unchanged)');
  run('cmake', ['--build', wasmBuildDir, '--parallel', jobs, '--target', 'core_tests_wasm'], { env: emccEnv });
}

/**
 * The native core and what the tests run: core_tests, and with OpenSubdiv
 * (libosd-dev) osd_tests and osd_reference. The benchmark's programs are
 * built by `npm run bench` itself.
 */
function buildNative() {
  const buildDir = join(root, 'build', 'native');
  log('building the native core and its tests');
  const targets = ['core_tests'];
  if (existsSync('/usr/include/opensubdiv/far/topologyRefiner.h')) targets.push('osd_tests', 'osd_reference');
  cmakeBuild(buildDir, ['cmake', '-S', 'wasm', '-B', buildDir, '-DCMAKE_BUILD_TYPE=Release'], targets);
}

function buildCli() {
  log('bundling the subdiv CLI');
  run(join(root, 'node_modules', '.bin', 'vite'), ['build', '--config', 'vite.cli.config.ts', '--logLevel', 'warn']);
  // npm exec runs a root package's own bin only in recent npm versions; a link
  // in node_modules/.bin makes `npx subdiv` work with any npm.
  const link = join(root, 'node_modules', '.bin', 'subdiv');
  try {
    lstatSync(link);
  } catch {
    symlinkSync(join('..', '..', 'bin', 'subdiv.mjs'), link);
  }
}

/** build/fuzz/subdivlab_fuzz and its fuzz_<target> links (tests/fuzz/CMakeLists.txt). */
function buildFuzz() {
  const buildDir = join(root, 'build', 'fuzz');
  log('building the fuzz targets (no-op when sources are unchanged)');
  cmakeBuild(buildDir, ['cmake', '-S', 'tests/fuzz', '-B', buildDir, '-DCMAKE_CXX_COMPILER=clang++-14']);
}

try {
  installDebianPackages();
  if (args.has('--fuzz')) {
    buildFuzz();
    process.exit(0);
  }
  if (!args.has('--wasm-only')) {
    installNpmDependencies();
    extractCgalMeshes();
  }
  buildWasm();
  await writeSchemeTable();
  if (args.has('--native')) buildNative();
  if (args.has('--wasm-tests')) buildWasmTests();
  if (!args.has('--wasm-only') && existsSync(join(root, 'vite.cli.config.ts'))) buildCli();
} catch (error) {
  console.error(`[setup] ${error.message}`);
  process.exit(1);
}
