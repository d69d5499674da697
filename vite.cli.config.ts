import { defineConfig } from 'vite';

/**
 * Bundles the Node entries into build/cli/: subdiv.mjs (the CLI, started by
 * bin/subdiv.mjs) and bench-wasm.mjs (the WASM side of scripts/bench.mjs).
 */
export default defineConfig({
  publicDir: false,
  build: {
    ssr: true,
    outDir: 'build/cli',
    emptyOutDir: true,
    target: 'node20',
    minify: false,
    rollupOptions: {
      input: { subdiv: 'web/cli/subdiv.ts', 'bench-wasm': 'web/cli/bench-wasm.ts' },
      output: { format: 'es', entryFileNames: '[name].mjs', chunkFileNames: 'chunks/[name]-[hash].mjs' },
    },
  },
});
