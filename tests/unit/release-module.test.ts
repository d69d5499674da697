/**
 * Test hooks stay out of what users get: the module the app and the CLI
 * load (web/core/generated/) has none, the test build these tests load
 * (build/wasm/test-module/, through vitest.config.ts) has them.
 */
import { readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { describe, expect, it } from 'vitest';

const HOOKS = ['throw_for_test'];

/** The functions a module built into `dir` (its glue and .wasm, which go together) exports. */
async function exportsOf(dir: string): Promise<Record<string, unknown>> {
  const { default: create } = await import(/* @vite-ignore */ pathToFileURL(join(dir, 'subdivlab.mjs')).href);
  return (await create({ wasmBinary: readFileSync(join(dir, 'subdivlab.wasm')) })) as Record<string, unknown>;
}

describe('test hooks', () => {
  it('are not in the shipped module, which has the API', async () => {
    const shipped = await exportsOf('web/core/generated');
    for (const hook of HOOKS) expect(typeof shipped[hook], hook).toBe('undefined');
    // heap_in_use is API: the worker reports the heap in use (memory requests).
    for (const name of ['subdivide', 'subdivide_view', 'read_mesh', 'predict_size', 'heap_in_use']) {
      expect(typeof shipped[name], name).toBe('function');
    }
  });

  it('are in the test build', async () => {
    const test = await exportsOf(dirname(process.env.SUBDIVLAB_WASM ?? ''));
    for (const hook of HOOKS) expect(typeof test[hook], hook).toBe('function');
  });
});
