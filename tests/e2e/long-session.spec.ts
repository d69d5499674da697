/**
 * A long session: 500 cycles of load, subdivide, scrub, reset and scheme
 * change, driven through the app's own controls in the page (a Playwright
 * round trip per action would take minutes). What it holds afterwards — GPU
 * geometries, the worker's WebAssembly heap and the levels it keeps — is
 * where it was after the first cycle.
 */
import { expect, test } from './fixtures';

const CYCLES = 500;

interface Holdings {
  gpuGeometries: number;
  heapInUse: number;
  memoryBytes: number;
  keptLevels: number;
}

test(`${CYCLES} cycles of load, subdivide, scrub, reset and scheme change hold no more than the first`, async ({
  app,
}) => {
  test.setTimeout(300_000);
  await app.open();
  // Cycles `from` to `to` − 1: one after another, they load a model other than the one shown.
  const run = (from: number, to: number) =>
    app.page.evaluate(
      async ([from, to]) => {
        const api = window.__subdivlab;
        if (!api) throw new Error('no test API');
        const byId = <T extends HTMLElement>(id: string) => {
          const element = document.querySelector<T>(`[data-testid="${id}"]`);
          if (!element) throw new Error(`no ${id}`);
          return element;
        };
        const until = async (what: string, done: () => boolean) => {
          const start = performance.now();
          while (!done()) {
            const state = api.state();
            if (state.lastError) throw new Error(`${what}: ${state.lastError.message}`);
            if (performance.now() - start > 20_000)
              throw new Error(`${what}: not done after 20 s (${JSON.stringify({ ...state, view: undefined })})`);
            await new Promise((resolve) => setTimeout(resolve, 2));
          }
        };
        const idle = () => !api.state().busy;
        // The controls follow the state a moment later: a disabled button ignores a click.
        const press = async (id: string) => {
          const button = byId<HTMLButtonElement>(id);
          await until(`${id} enabled`, () => !button.disabled);
          button.click();
        };
        const samples = ['icosahedron', 'octahedron', 'cube', 'tetrahedron'];
        const schemes = ['loop', 'catmull-clark', 'sqrt3', 'doo-sabin'];
        const scrubber = byId<HTMLInputElement>('controls.level');
        const menu = byId<HTMLSelectElement>('controls.scheme');
        for (let i = from; i < to; i++) {
          const name = samples[i % samples.length];
          await press(`gallery.${name}`);
          await until(`cycle ${i}: load ${name}`, () => idle() && api.state().modelName === `${name}.off`);
          for (const count of [2, 3]) {
            await press('controls.subdivide');
            await until(`cycle ${i}: level ${count - 1}`, () => idle() && api.state().levelCount === count);
          }
          for (const level of [0, 1, 2]) {
            await until(`cycle ${i}: scrubber enabled`, () => !scrubber.disabled);
            scrubber.value = String(level);
            scrubber.dispatchEvent(new Event('input', { bubbles: true }));
            await until(`cycle ${i}: scrub to ${level}`, () => api.state().level === level);
          }
          await press('controls.reset');
          await until(`cycle ${i}: reset`, () => idle() && api.state().levelCount === 1);
          const scheme = schemes[i % schemes.length];
          menu.value = scheme;
          menu.dispatchEvent(new Event('change', { bubbles: true }));
          await until(`cycle ${i}: ${scheme}`, () => idle() && api.state().scheme === scheme);
        }
      },
      [from, to],
    );
  const holdings = async (): Promise<Holdings> => {
    // The view lets go of a level's GPU buffers in the frame after; the worker answers after its queue.
    await app.page.evaluate(
      () => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))),
    );
    const memory = await app.page.evaluate(() => window.__subdivlab?.coreMemory());
    if (!memory) throw new Error('no core memory');
    const { heapInUse, memoryBytes, keptLevels } = memory;
    return { gpuGeometries: (await app.state()).gpuGeometries, heapInUse, memoryBytes, keptLevels };
  };

  await run(0, 1);
  const first = await holdings();
  const start = Date.now();
  await run(1, CYCLES);
  const seconds = (Date.now() - start) / 1000;
  const last = await holdings();
  console.log(
    `long session: ${CYCLES - 1} cycles in ${seconds.toFixed(1)} s; after the first → after the last: ` +
      `GPU geometries ${first.gpuGeometries} → ${last.gpuGeometries}, ` +
      `WASM heap in use ${first.heapInUse} → ${last.heapInUse} bytes, ` +
      `WASM memory ${first.memoryBytes} → ${last.memoryBytes} bytes, kept levels ${first.keptLevels} → ${last.keptLevels}`,
  );
  // Every cycle ends on the same kind of state (a model's level 0 after a scheme change).
  expect(last.gpuGeometries).toBe(first.gpuGeometries);
  expect(last.keptLevels).toBe(first.keptLevels);
  // The slack: 64 kB of the allocator's own bookkeeping (a leak of one level 2 a cycle would be 20 MB).
  expect(Math.abs(last.heapInUse - first.heapInUse)).toBeLessThanOrEqual(64 * 1024);
  expect(last.memoryBytes).toBe(first.memoryBytes);
});
