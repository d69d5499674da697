import { fileURLToPath } from 'node:url';
import { defineConfig, type Plugin } from 'vite';
import { loaderScript } from './vite.embed.config.ts';
import { policyMetaTag } from './web/site/content-security-policy.ts';

const page = (path: string) => fileURLToPath(new URL(path, import.meta.url));

/**
 * Writes the site's Content-Security-Policy into each built page's head,
 * first, so it covers everything after it. Only in builds: the dev server's
 * hot reload injects what the policy refuses.
 */
function contentSecurityPolicy(): Plugin {
  return {
    name: 'subdivlab-content-security-policy',
    apply: 'build',
    transformIndexHtml: {
      order: 'post',
      handler: (html) => html.replace(/<head>/, `<head>\n    ${policyMetaTag()}`),
    },
  };
}

/**
 * In the dev server, embed/subdiv-viewer.js (the built loader's name, as
 * public/examples/ and the Embed dialog's snippets write it) is the loader
 * importing the element's source, and embed/iframe-route.js (embed.html's
 * script) its source; `vite build -c vite.embed.config.ts` makes the real
 * files. And examples/ is its index page, as a static host serves it (the
 * dev server would answer with the app).
 */
function embedModuleInDev(): Plugin {
  return {
    name: 'subdivlab-embed-module-in-dev',
    configureServer(server) {
      server.middlewares.use((request, response, next) => {
        const url = request.url ?? '';
        if (url.startsWith('/embed/subdiv-viewer.js')) {
          loaderScript('./subdiv-viewer.ts').then((code) => {
            response.setHeader('content-type', 'text/javascript');
            response.end(code);
          }, next);
          return;
        }
        if (url.startsWith('/embed/iframe-route.js')) {
          request.url = url.replace('/embed/iframe-route.js', '/embed/iframe-route.ts');
        } else if (/^\/examples\/?(\?|$)/.test(url)) {
          request.url = url.replace(/^\/examples\/?/, '/examples/index.html');
        }
        next();
      });
    },
  };
}

// The app lives in web/; sample meshes in public/ are served as-is. A relative
// base makes the built site work from any sub-path of any static host.
// Two pages: the app (index.html) and the iframe route (embed.html, whose script
// vite.embed.config.ts builds with the element's, so they share three.js).
export default defineConfig({
  root: 'web',
  publicDir: '../public',
  base: './',
  plugins: [embedModuleInDev(), contentSecurityPolicy()],
  build: {
    outDir: '../dist',
    emptyOutDir: true,
    target: 'es2022',
    // three.js alone is about 550 kB minified (150 kB gzip); it is one chunk on purpose.
    chunkSizeWarningLimit: 700,
    rollupOptions: {
      input: { index: page('web/index.html'), embed: page('web/embed.html') },
    },
  },
  worker: {
    // A classic worker: started from a blob: with importScripts on other hosts (worker-client.ts).
    format: 'iife',
  },
  server: {
    host: '127.0.0.1',
  },
  preview: {
    host: '127.0.0.1',
    // Access-Control-Allow-Origin: * for every origin, as public static hosts send it: the e2e
    // tests' sandboxed frames (origin null) load the element from here, which Vite's default
    // (localhost origins only) refuses. A test server setting; the built files are unchanged.
    cors: true,
  },
});
