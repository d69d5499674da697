import { defineConfig } from 'vite';

/** Bundles the `subdiv` CLI for Node into build/cli/subdiv.mjs (started by bin/subdiv.mjs). */
export default defineConfig({
  publicDir: false,
  build: {
    ssr: 'web/cli/subdiv.ts',
    outDir: 'build/cli',
    emptyOutDir: true,
    target: 'node20',
    minify: false,
    rollupOptions: {
      output: { format: 'es', entryFileNames: 'subdiv.mjs' },
    },
  },
});
