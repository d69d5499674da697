import { defineConfig } from 'vitest/config';

/** Node tests against the real WASM core (tests/unit); they load it through initNode(). */
export default defineConfig({
  test: {
    include: ['tests/unit/**/*.test.ts'],
    environment: 'node',
    testTimeout: 120_000,
    hookTimeout: 60_000,
  },
});
