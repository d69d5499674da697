// The app part of `npm run bench` (called by bench.mjs, or alone:
// node scripts/bench-app.mjs [--runs N]): the built site (dist/, rebuilt
// when web/ or public/ is newer) served by `vite preview` on a free
// loopback port (SUBDIVLAB_BENCH_PORT to choose one), Debian's Chromium
// driven by Playwright as in playwright.config.ts, WebGL through SwiftShader.
//
// Per row: the app opens the row's mesh (bunny00, or CGAL's refined_elephant for
// the 17 M-face row) with its scheme at one level below
// the row's (`#src=…&scheme=…&levels=…`), waits until it is drawn and idle,
// then clicks Subdivide. Time to screen: from the click event's timeStamp to
// the end of the first draw of the new level (the test API's `drawn.at`:
// the view's renderer has drawn it and its picture was copied into the
// page's canvas, which reads the GPU's result back, so the upload and the
// rasterisation are included; the compositor shows that canvas with the
// frame). The longest main-thread task in that span comes from Chrome's
// trace (top-level tasks of the page's main thread, any length; a long task
// in the Long Tasks API's sense is one over 50 ms). The last run's trace of
// each row is kept in build/bench-app/ (open it in DevTools' Performance tab).
import { spawnSync } from 'node:child_process';
import { copyFileSync, existsSync, mkdirSync, readdirSync, statSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const CHROMIUM = '/usr/bin/chromium';
/**
 * Two levels of bunny00 (72 k triangles): Loop 1.2 M triangles, Catmull-Clark
 * 905 k quads, three runs each; then, once, Catmull-Clark level 4 of CGAL's
 * refined_elephant (44 k triangles): 17 M quads from the 4.3 M of level 3,
 * past the tab's memory budget, so the app asks first and the bench confirms.
 */
const ROWS = [
  { scheme: 'loop', levels: 2, mesh: 'bunny00' },
  { scheme: 'catmull-clark', levels: 2, mesh: 'bunny00' },
  { scheme: 'catmull-clark', levels: 4, mesh: 'refined_elephant', runs: 1, confirm: true },
];
/** Where the site serves a mesh: bunny00 is a sample; others are copied into dist/meshes/bench/. */
const siteMesh = (name) => (name === 'bunny00' ? 'meshes/cgal/bunny00.off' : `meshes/bench/${name}.off`);
/** As playwright.config.ts launches it: WebGL on the CPU through SwiftShader. */
const LAUNCH_ARGS = [
  '--no-sandbox',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  '--no-first-run',
  '--use-angle=swiftshader',
  '--enable-unsafe-swiftshader',
];
const TRACE_CATEGORIES = ['toplevel', 'devtools.timeline', 'blink.user_timing'];
/** Thread names in Chrome's trace. */
const MAIN_THREAD = 'CrRendererMain';
const WORKER_THREAD = 'DedicatedWorker thread';

/** Newest modification time under `path` (ms). */
function newest(path) {
  const stat = statSync(path);
  if (!stat.isDirectory()) return stat.mtimeMs;
  return readdirSync(path).reduce((t, name) => Math.max(t, newest(join(path, name))), stat.mtimeMs);
}

/** Builds dist/ unless it is newer than the app's sources and the public files. */
function ensureSite() {
  const index = join(root, 'dist', 'index.html');
  const sources = Math.max(
    ...['web', 'public', 'vite.config.ts', 'vite.embed.config.ts'].map((p) => newest(join(root, p))),
  );
  if (existsSync(index) && statSync(index).mtimeMs >= sources) return;
  console.log('[bench] app: building the site (npm run build:site)');
  const r = spawnSync('npm', ['run', 'build:site', '--silent'], { cwd: root, stdio: ['ignore', 'ignore', 'inherit'] });
  if (r.status !== 0) throw new Error(`npm run build:site failed with status ${r.status}`);
}

/** dist/ served by vite preview on a loopback port; resolves with its URL and a close function. */
async function serveSite() {
  const { preview } = await import('vite');
  const port = Number(process.env.SUBDIVLAB_BENCH_PORT ?? 0);
  const server = await preview({
    // vite.config.ts's root ('web', relative to the working directory) from anywhere.
    root: join(root, 'web'),
    configFile: join(root, 'vite.config.ts'),
    logLevel: 'warn',
    preview: { host: '127.0.0.1', port, strictPort: true, open: false },
  });
  const address = server.httpServer.address();
  return {
    url: `http://127.0.0.1:${address.port}/`,
    close: () => new Promise((resolve) => server.httpServer.close(resolve)),
  };
}

const median = (values) => {
  const sorted = [...values].sort((a, b) => a - b);
  const mid = sorted.length >> 1;
  return sorted.length % 2 ? sorted[mid] : (sorted[mid - 1] + sorted[mid]) / 2;
};

/**
 * The page's main thread and its core worker in a Chrome trace, found by the
 * user-timing mark `sync` the page made at performance.now() = `syncNow`;
 * returns their top-level tasks in the page's performance.now() milliseconds.
 */
function tasksOf(trace, sync, syncNow) {
  const events = trace.traceEvents;
  const mark = events.find((e) => e.name === sync && e.cat.includes('blink.user_timing'));
  if (!mark) throw new Error(`trace: mark ${sync} not found`);
  const offset = mark.ts / 1000 - syncNow;
  const threadName = new Map();
  for (const e of events) {
    if (e.ph === 'M' && e.name === 'thread_name') threadName.set(`${e.pid}:${e.tid}`, e.args.name);
  }
  const main = `${mark.pid}:${mark.tid}`;
  const tasks = { main: [], worker: [] };
  for (const e of events) {
    if (e.ph !== 'X' || e.cat !== 'toplevel' || e.pid !== mark.pid) continue;
    const thread = `${e.pid}:${e.tid}`;
    const kind = thread === main ? 'main' : threadName.get(thread) === WORKER_THREAD ? 'worker' : null;
    if (!kind || threadName.get(main) !== MAIN_THREAD) continue;
    // Nested RunTask events (a task inside a task) count once, as their outermost.
    tasks[kind].push({ start: e.ts / 1000 - offset, ms: (e.dur ?? 0) / 1000, name: e.name });
  }
  for (const list of Object.values(tasks)) {
    list.sort((a, b) => a.start - b.start);
    let end = -Infinity;
    for (let i = 0; i < list.length; i++) {
      if (list[i].start < end) list.splice(i--, 1);
      else end = list[i].start + list[i].ms;
    }
  }
  return tasks;
}

/** One timed step: opens the app at level `levels` − 1, clicks Subdivide, waits for level `levels` drawn. */
async function timeStep(browser, url, row, run, traceDir) {
  const context = await browser.newContext({ viewport: { width: 1024, height: 700 }, deviceScaleFactor: 1 });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (error) => errors.push(error.message));
  try {
    const before = row.levels - 1;
    await page.goto(`${url}#src=${siteMesh(row.mesh)}&scheme=${row.scheme}&levels=${before}`);
    await page.waitForFunction(
      (k) => {
        const s = window.__subdivlab?.state();
        if (s?.lastError) throw new Error(s.lastError.message);
        return s?.ready && !s.busy && s.level === k && s.drawn?.level === k;
      },
      before,
      { timeout: 300_000, polling: 100 },
    );
    // Let the page settle (the hash is written about 300 ms after a change, garbage collected).
    await page.waitForTimeout(1000);
    await page.evaluate(() => {
      window.__benchClick = null;
      document.addEventListener('click', (event) => (window.__benchClick = event.timeStamp), {
        capture: true,
        once: true,
      });
    });
    const sync = `subdivlab-bench-${row.scheme}-${run}`;
    await browser.startTracing(page, { categories: TRACE_CATEGORIES });
    const syncNow = await page.evaluate((name) => performance.mark(name).startTime, sync);
    // Each animation frame, until the view has drawn level k: then, in a task
    // of its own (kept out of the longest task), a 1-pixel read-back of the
    // view's canvas, which waits for the GPU's work on it.
    const shown = page.evaluate(
      (k) =>
        new Promise((resolve, reject) => {
          const poll = () => {
            const s = window.__subdivlab?.state();
            if (s?.lastError) return reject(new Error(s.lastError.message));
            if (s?.drawn?.level !== k) return requestAnimationFrame(poll);
            setTimeout(() => {
              document.querySelector('canvas.subdiv-canvas').getContext('2d').getImageData(0, 0, 1, 1);
              resolve({ drawn: s.drawn.at, screen: performance.now(), click: window.__benchClick, state: s });
            });
          };
          requestAnimationFrame(poll);
        }),
      row.levels,
    );
    await page.getByTestId('controls.subdivide').click();
    if (row.confirm) {
      // The step is past the memory budget: the app asks, the bench says yes.
      await page.getByTestId('confirm.ok').click({ timeout: 60_000 });
    }
    const { drawn, screen, click, state } = await shown;
    const trace = JSON.parse((await browser.stopTracing()).toString('utf8'));
    if (errors.length > 0) throw new Error(`page error: ${errors.join('; ')}`);
    if (click === null) throw new Error('the click on Subdivide was not seen');
    const tasks = tasksOf(trace, sync, syncNow);
    const during = (list) => list.filter((t) => t.start + t.ms > click && t.start < drawn);
    const main = during(tasks.main);
    const worker = during(tasks.worker);
    const longest = main.reduce((a, t) => (t.ms > a.ms ? t : a), { ms: 0, start: click });
    if (traceDir) {
      mkdirSync(traceDir, { recursive: true });
      writeFileSync(join(traceDir, `${row.scheme}-${row.mesh}-L${row.levels}.json`), JSON.stringify(trace));
    }
    return {
      faces: state.facts.faces,
      ms: screen - click,
      drawn_ms: drawn - click,
      longest_task_ms: longest.ms,
      longest_task_at_ms: longest.start - click,
      main_busy_ms: main.reduce((s, t) => s + t.ms, 0),
      worker_busy_ms: worker.reduce((s, t) => s + t.ms, 0),
      // The facts panel's "Last step": the core's subdivide() call in the worker.
      core_ms: Number.parseFloat(await page.getByTestId('facts.time').textContent()),
      main_tasks_over_16ms: main.filter((t) => t.ms > 16).map((t) => ({ at: t.start - click, ms: t.ms })),
      worker_tasks_over_16ms: worker.filter((t) => t.ms > 16).map((t) => ({ at: t.start - click, ms: t.ms })),
    };
  } finally {
    await context.close();
  }
}

/**
 * Runs every row `runs` times (the 17 M-face row once, when `meshes` has its
 * mesh: name → path of an OFF file); returns the rows with medians (and the runs).
 */
export async function benchApp(runs = 3, meshes = {}) {
  if (!existsSync(CHROMIUM)) {
    console.log(`[bench] app: ${CHROMIUM} not found (Debian's chromium): no app rows`);
    return [];
  }
  ensureSite();
  const rowsToRun = ROWS.filter((row) => row.mesh === 'bunny00' || meshes[row.mesh]);
  for (const row of rowsToRun) {
    if (row.mesh === 'bunny00') continue;
    mkdirSync(join(root, 'dist', 'meshes', 'bench'), { recursive: true });
    copyFileSync(meshes[row.mesh], join(root, 'dist', siteMesh(row.mesh)));
  }
  const { chromium } = await import('@playwright/test');
  const server = await serveSite();
  const browser = await chromium.launch({ executablePath: CHROMIUM, args: LAUNCH_ARGS });
  const traceDir = join(root, 'build', 'bench-app');
  const rows = [];
  try {
    for (const row of rowsToRun) {
      const times = row.runs ?? runs;
      console.log(
        `[bench] app: ${row.scheme}, ${row.mesh} x${row.levels} in Chromium (${server.url}), ${times} run(s)`,
      );
      const all = [];
      for (let run = 0; run < times; run++) {
        all.push(await timeStep(browser, server.url, row, run, run === times - 1 ? traceDir : null));
      }
      rows.push({
        scheme: row.scheme,
        mesh: `${row.mesh} x${row.levels}`,
        faces: all[0].faces,
        ms_to_screen: median(all.map((r) => r.ms)),
        longest_task_ms: median(all.map((r) => r.longest_task_ms)),
        runs: all,
      });
    }
  } finally {
    await browser.close();
    await server.close();
  }
  return rows;
}

/** Prints the app table. */
export function printApp(rows, runs) {
  if (rows.length === 0) return;
  const pad = (s, n) => String(s).padEnd(n);
  const num = (x) => x.toFixed(0).padStart(14);
  const med = (r, key) => median(r.runs.map((x) => x[key]));
  console.log(
    `\nthe app's time to screen (Chromium, WebGL on SwiftShader; median of ${runs} runs; the 17 M-face row, one run)`,
  );
  const head = ['faces', 'ms to screen', 'longest task', 'ms to draw', 'core ms', 'main busy'];
  console.log(`${pad('scheme', 15)}${pad('mesh', 22)}${head.map((h) => h.padStart(14)).join('')}`);
  for (const r of rows) {
    console.log(
      `${pad(r.scheme, 15)}${pad(r.mesh, 22)}${String(r.faces).padStart(14)}${num(r.ms_to_screen)}${num(r.longest_task_ms)}` +
        `${num(med(r, 'drawn_ms'))}${num(med(r, 'core_ms'))}${num(med(r, 'main_busy_ms'))}`,
    );
  }
  console.log(
    '(from the click on Subdivide: ms to screen, until the new level is drawn and its pixels read back from the canvas; ' +
      'longest task: on the main thread until the draw, from the trace; ms to draw: until the draw was issued; ' +
      "core ms: subdivide() in the worker (facts panel); main busy: the main thread's tasks until the draw; traces in build/bench-app/)",
  );
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const argv = process.argv.slice(2);
  const runsAt = argv.indexOf('--runs');
  const runs = runsAt >= 0 ? Number(argv[runsAt + 1]) : 3;
  const rows = await benchApp(runs);
  printApp(rows, runs);
  if (process.env.SUBDIVLAB_BENCH_DUMP) console.log(JSON.stringify(rows, null, 2));
}
