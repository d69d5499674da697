import { defineConfig } from 'vite';

// The app lives in web/; sample meshes in public/ are served as-is. A relative
// base makes the built site work from any sub-path of any static host.
export default defineConfig({
  root: 'web',
  publicDir: '../public',
  base: './',
  build: {
    outDir: '../dist',
    emptyOutDir: true,
    target: 'es2022',
    // three.js alone is about 550 kB minified (150 kB gzip); it is one chunk on purpose.
    chunkSizeWarningLimit: 700,
  },
  worker: {
    format: 'es',
  },
  server: {
    host: '127.0.0.1',
  },
  preview: {
    host: '127.0.0.1',
  },
});
