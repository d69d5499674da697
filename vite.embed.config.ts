import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vite';

/**
 * The `<subdiv-viewer>` element as a self-contained folder, dist/embed/:
 * subdiv-viewer.js (the element, three.js included), its worker and the
 * `.wasm` under assets/, all found relative to the module's own URL, so a
 * teacher can copy the folder next to a page or point at a hosted copy.
 * Runs after the app's build (vite.config.ts), which empties dist/.
 */
export default defineConfig({
  root: 'web',
  publicDir: false,
  base: './',
  build: {
    outDir: '../dist/embed',
    emptyOutDir: true,
    target: 'es2022',
    // three.js is most of it, on purpose in one file: one request for a page's viewers.
    chunkSizeWarningLimit: 800,
    rollupOptions: {
      input: { 'subdiv-viewer': fileURLToPath(new URL('web/embed/subdiv-viewer.ts', import.meta.url)) },
      preserveEntrySignatures: 'exports-only',
      output: {
        entryFileNames: '[name].js',
        chunkFileNames: 'assets/[name]-[hash].js',
        assetFileNames: 'assets/[name]-[hash][extname]',
      },
    },
  },
  worker: {
    // A classic worker: started from a blob: with importScripts on other hosts (worker-client.ts).
    format: 'iife',
  },
});
