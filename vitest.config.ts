import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vitest/config';

/**
 * Node tests against the real WASM core (tests/unit); they load it through
 * initNode(), here the test build of the module (wasm target subdivlab_test:
 * the shipped module and its test hooks, throw_for_test and heap_in_use).
 */
const testModule = (file: string) => fileURLToPath(new URL(`build/wasm/test-module/${file}`, import.meta.url));

export default defineConfig({
  resolve: {
    // subdiv-core.ts's import of the glue; its .wasm comes through SUBDIVLAB_WASM (init-node.ts).
    alias: [{ find: /^\.\/generated\/subdivlab\.mjs$/, replacement: testModule('subdivlab.mjs') }],
  },
  test: {
    env: { SUBDIVLAB_WASM: testModule('subdivlab.wasm') },
    include: ['tests/unit/**/*.test.ts'],
    environment: 'node',
    testTimeout: 120_000,
    hookTimeout: 60_000,
  },
});
