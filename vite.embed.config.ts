import { readFile } from 'node:fs/promises';
import { fileURLToPath } from 'node:url';
import { defineConfig, type Plugin, transformWithOxc } from 'vite';

const source = (path: string) => fileURLToPath(new URL(path, import.meta.url));

/** The marker in subdiv-viewer-loader.ts that the element module's path replaces. */
const MODULE_MARKER = '__SUBDIVLAB_ELEMENT_MODULE__';

/**
 * subdiv-viewer-loader.ts as a classic script importing `modulePath` (from
 * the script's own URL). It imports nothing, so stripping its types is the
 * whole build; the dev server (vite.config.ts) serves it the same way.
 */
export async function loaderScript(modulePath: string): Promise<string> {
  const file = source('web/embed/subdiv-viewer-loader.ts');
  const { code } = await transformWithOxc(await readFile(file, 'utf8'), file, { lang: 'ts' });
  if (!code.includes(MODULE_MARKER)) throw new Error(`${file} lost its marker ${MODULE_MARKER}`);
  return code.replace(MODULE_MARKER, modulePath);
}

/**
 * Writes subdiv-viewer.js, the file pages include, as the classic loader of
 * the element's module (assets/subdiv-viewer-*.js): a module from a host
 * without CORS never runs, where a classic script does and can say why.
 */
function classicLoader(): Plugin {
  return {
    name: 'subdivlab-classic-loader',
    apply: 'build',
    async generateBundle(_options, bundle) {
      const element = Object.values(bundle).find((c) => c.type === 'chunk' && c.isEntry && c.name === 'subdiv-viewer');
      if (!element) throw new Error('the element module (entry subdiv-viewer) is missing from the bundle');
      this.emitFile({
        type: 'asset',
        fileName: 'subdiv-viewer.js',
        source: await loaderScript(`./${element.fileName}`),
      });
    },
  };
}

/**
 * The `<subdiv-viewer>` element and the iframe route as a self-contained
 * folder, dist/embed/: subdiv-viewer.js (the loader pages include), the
 * element's module and iframe-route.js (embed.html's script) on one shared
 * chunk with three.js, the worker and the `.wasm` under assets/, all found
 * relative to the modules' own URLs, so a teacher can copy the folder next
 * to a page or point at a hosted copy. A page holding both an element and
 * an iframe of embed.html fetches three.js once: the same chunk, from the
 * browser's cache the second time. Runs after the app's build
 * (vite.config.ts), which empties dist/ and writes embed.html.
 */
export default defineConfig({
  root: 'web',
  publicDir: false,
  base: './',
  plugins: [classicLoader()],
  build: {
    outDir: '../dist/embed',
    emptyOutDir: true,
    target: 'es2022',
    // three.js is most of the shared chunk, on purpose in one file: one request for a page's viewers.
    chunkSizeWarningLimit: 800,
    rollupOptions: {
      input: {
        'subdiv-viewer': source('web/embed/subdiv-viewer.ts'),
        'iframe-route': source('web/embed/iframe-route.ts'),
      },
      preserveEntrySignatures: 'exports-only',
      output: {
        // embed.html names iframe-route.js; the loader finds the element's hashed name.
        entryFileNames: (chunk) => (chunk.name === 'iframe-route' ? '[name].js' : 'assets/[name]-[hash].js'),
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
