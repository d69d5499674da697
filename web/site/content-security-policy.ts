/**
 * The Content-Security-Policy of the built site (the app, the iframe route
 * and the example page), declared in each page's head (vite.config.ts
 * writes it into the app's pages at build time; the example page carries it
 * as written). No inline script or style; WebAssembly compiles
 * ('wasm-unsafe-eval', the core's module is compiled on the page); the core's
 * worker comes from the site (or a blob: of the page that imports it, in a
 * sandboxed frame); `?src=` may fetch a mesh from any https host
 * (as well as the site itself), nothing else is fetched; pictures and Copy
 * image use data: and blob: images.
 */
export const CONTENT_SECURITY_POLICY = [
  "default-src 'self'",
  "script-src 'self' 'wasm-unsafe-eval'",
  "style-src 'self'",
  "img-src 'self' data: blob:",
  "connect-src 'self' https:",
  // blob: for the iframe route in a frame with sandbox="allow-scripts": its origin is opaque, so
  // the worker starts from a blob: of the page (worker-client.ts), which 'self' does not cover.
  "worker-src 'self' blob:",
  "object-src 'none'",
  "base-uri 'self'",
  "form-action 'none'",
].join('; ');

/** The policy as the `<meta>` element a page's head carries. */
export function policyMetaTag(policy = CONTENT_SECURITY_POLICY): string {
  return `<meta http-equiv="Content-Security-Policy" content="${policy}" />`;
}
