/**
 * dist/embed/subdiv-viewer.js, the file a page includes: a small classic
 * script (no import or export, so `<script src>` and `<script type="module"
 * src>` both run it) that adds the element's module beside it to the page.
 * A module from another host needs CORS, where a classic script does not: on
 * a host that sends no `Access-Control-Allow-Origin`, the module fails, and
 * this script defines `<subdiv-viewer>` as a box saying so, with the iframe route
 * (`embed.html`, which needs no CORS) as the way round. Nothing else stays
 * empty: each element shows the box and fires `error`.
 *
 * embed.html (the iframe route) includes it too, with `data-route`: then it
 * adds the route's module (iframe-route.js) instead, and where that cannot
 * run (a frame with `sandbox="allow-scripts"`, whose opaque origin makes
 * every file a cross-origin one, on a host without CORS) the box fills the
 * frame and its reason goes to the parent page as an `error` message.
 *
 * Built by vite.embed.config.ts (classicLoader), which writes the module's
 * file name in place of the marker below; it imports nothing, so that the
 * build only strips its types.
 */
(() => {
  /** The element module's path from this script, set by the build. */
  const ELEMENT_MODULE = '__SUBDIVLAB_ELEMENT_MODULE__';
  /** The iframe route's module, beside this script. */
  const ROUTE_MODULE = './iframe-route.js';

  /** Why the module did not run, as the box and the `error` event say it. */
  interface Unavailable {
    /** The sentences of the box, in order. */
    lines: string[];
    /** The message of the `error` event. */
    message: string;
  }

  const current = document.currentScript instanceof HTMLScriptElement ? document.currentScript : null;
  /** In embed.html: the page is one viewer, made by the route's module. */
  const route = current?.hasAttribute('data-route') ?? false;
  const scriptUrl = ownUrl();
  const moduleUrl = new URL(route ? ROUTE_MODULE : ELEMENT_MODULE, scriptUrl).href;
  // A module script element rather than import(): while it loads it holds the page's load
  // event, so the element is defined by then, as when pages included the module itself.
  const module = document.createElement('script');
  module.type = 'module';
  module.src = moduleUrl;
  if (current?.nonce) module.nonce = current.nonce;
  module.addEventListener('error', () => void unavailable('the browser did not load it'));
  // Loaded and run, but no element: it failed while running (the console says why).
  module.addEventListener('load', () => void unavailable('it stopped while running'));
  document.head.append(module);

  async function unavailable(said: string): Promise<void> {
    if (customElements.get('subdiv-viewer')) return;
    const why = await diagnose(moduleUrl, said);
    if (customElements.get('subdiv-viewer')) return;
    customElements.define('subdiv-viewer', unavailableElement(why));
    if (route) showInRoute();
  }

  /** The iframe route's page as the box, its reason posted to the parent as the route posts errors. */
  function showInRoute(): void {
    const box = document.createElement('subdiv-viewer');
    // Styled here, as the site's policy refuses inline styles (as iframe-route.ts does).
    for (const element of [document.documentElement, document.body])
      element.style.cssText = 'margin:0;height:100%;overflow:hidden';
    box.style.cssText = 'position:fixed;inset:0;width:100%;height:auto;border-radius:0';
    box.addEventListener('error', (event) => {
      if (window.parent === window) return;
      const detail = (event as unknown as CustomEvent<Record<string, unknown>>).detail;
      window.parent.postMessage({ subdivlab: 'error', ...detail }, '*');
    });
    document.body.append(box);
  }

  /**
   * This script's URL: `document.currentScript` as a classic script; as a
   * module (no currentScript) the page's script that names this file, else
   * the URL in a stack trace, which every browser writes.
   */
  function ownUrl(): string {
    if (current?.src) return current.src;
    for (const script of document.querySelectorAll<HTMLScriptElement>('script[src]')) {
      if (/\/subdiv-viewer\.js([?#]|$)/.test(script.src)) return script.src;
    }
    const inStack = /(https?:\/\/[^\s)]+?\.js)(?:[?#][^\s):]*)?:\d+:\d+/.exec(new Error().stack ?? '');
    return inStack ? inStack[1] : new URL('embed/subdiv-viewer.js', document.baseURI).href;
  }

  /**
   * Tells a host without CORS from one that is down or lacks the file: a
   * CORS request that fails while a no-cors one gets an answer means the
   * server is there and sends no `Access-Control-Allow-Origin`.
   */
  async function diagnose(url: string, said: string): Promise<Unavailable> {
    const host = new URL(url).origin;
    try {
      const response = await fetch(url, { cache: 'no-store' });
      if (!response.ok) {
        return {
          lines: [`The SubdivLab module ${url} is not there (HTTP ${response.status}).`, copyHint()],
          message: `The SubdivLab module ${url} could not be loaded: HTTP ${response.status}.`,
        };
      }
      return {
        lines: [
          `The SubdivLab module ${url} did not run on this page: ${said}.`,
          // The module is there; what it imports (assets/) may not be, which this check cannot see.
          `Check that the files it imports are there too (${new URL('assets/', scriptUrl).href}: copy the whole embed/ folder), and, if the page has a Content-Security-Policy, that its script-src allows ${host}.`,
        ],
        message: `The SubdivLab module ${url} did not run: ${said}.`,
      };
    } catch {
      const answered = await fetch(url, { mode: 'no-cors', cache: 'no-store' }).then(
        () => true,
        () => false,
      );
      if (!answered || host === self.origin) {
        return {
          lines: [`The SubdivLab module ${url} could not be loaded (${said}).`, copyHint()],
          message: `The SubdivLab module ${url} could not be loaded: ${said}`,
        };
      }
      const sandboxed = self.origin === 'null';
      const who = sandboxed ? 'this sandboxed frame (origin null)' : self.origin;
      const lines = [
        `${host} does not send CORS headers, so the browser will not run SubdivLab's module on this page.`,
        `The host must send Access-Control-Allow-Origin: * (or ${who}) with the files under ${new URL('.', scriptUrl).pathname}.`,
      ];
      // Same origin, no CORS: in embed.html, a frame that keeps its origin loads the route from its own host.
      if (sandboxed && route) {
        lines.push(
          'This page is in a frame with sandbox="allow-scripts", whose origin is opaque, so every file comes from another origin. ' +
            "Adding allow-same-origin to the frame's sandbox gives it its own origin back, which needs no CORS.",
        );
      }
      return {
        lines,
        message:
          `${host} sends no CORS headers (Access-Control-Allow-Origin), so the module ${url} cannot run on this page; ` +
          'the iframe route (embed.html) needs none.',
      };
    }
  }

  function copyHint(): string {
    return 'Copy the whole embed/ folder of the build (subdiv-viewer.js and assets/) next to the page.';
  }

  /**
   * `<subdiv-viewer>` as the box, at the element's size: the reason, and the
   * iframe route with the element's own settings, as a link and a button
   * that puts it in the box's place.
   */
  function unavailableElement(unavailable: Unavailable): CustomElementConstructor {
    return class SubdivViewerUnavailable extends HTMLElement {
      connectedCallback(): void {
        if (this.shadowRoot) return;
        const root = this.attachShadow({ mode: 'open' });
        const box = document.createElement('div');
        box.className = 'box';
        box.setAttribute('part', 'message');
        box.setAttribute('role', 'alert');
        const title = document.createElement('strong');
        title.textContent = 'The SubdivLab viewer cannot start here.';
        box.append(title);
        for (const line of unavailable.lines) {
          const p = document.createElement('p');
          p.textContent = line;
          box.append(p);
        }
        appendStyles(root);
        root.append(box);
        if (!route) box.append(routeParagraph(this, box));
        this.dispatchEvent(
          new CustomEvent('error', {
            detail: { code: 'load_error', message: unavailable.message, line: 0, source: moduleUrl },
            bubbles: true,
            composed: true,
          }),
        );
      }
    };
  }

  /** The iframe route with `element`'s settings, as a link and a button that puts it in `box`'s place. */
  function routeParagraph(element: HTMLElement, box: HTMLElement): HTMLElement {
    const href = iframeRoute(element);
    const p = document.createElement('p');
    const link = document.createElement('a');
    link.href = href;
    link.target = '_blank';
    link.rel = 'noopener';
    // The query as a teacher would type it: values decoded, spaces as spaces.
    const query = [...new URL(href).searchParams].map(([key, value]) => `${key}=${value}`).join('&');
    link.textContent = `embed.html?${query}`;
    p.append('Or use the iframe route, which needs no CORS: ', link, '. ');
    const show = document.createElement('button');
    show.type = 'button';
    show.setAttribute('part', 'show-iframe');
    show.textContent = 'Show it here';
    // The student sees the model now; the box comes back when the page is loaded again.
    show.addEventListener('click', () => {
      const frame = document.createElement('iframe');
      frame.src = href;
      frame.title = element.getAttribute('alt') ?? 'SubdivLab viewer';
      frame.setAttribute('part', 'iframe');
      box.replaceWith(frame);
    });
    p.append(show);
    return p;
  }

  /** embed.html beside embed/, with the element's attributes as its query (names as in the share link). */
  function iframeRoute(element: HTMLElement): string {
    const url = new URL('../embed.html', scriptUrl);
    const keys: Record<string, string> = { 'render-mode': 'mode', 'line-width': 'lines' };
    for (const { name, value } of Array.from(element.attributes)) {
      if (name === 'id' || name === 'class' || name === 'style' || name === 'tabindex') continue;
      // URLs relative to the page, which the route would read relative to its own.
      if (name === 'src' || name === 'rules') url.searchParams.set(name, new URL(value, document.baseURI).href);
      else if (name === 'beside')
        url.searchParams.set(
          'beside',
          value
            .trim()
            .split(/[\s,]+/)
            .join(','),
        );
      else url.searchParams.set(keys[name] ?? name, value);
    }
    return url.href;
  }

  const CSS = `
:host { display: block; position: relative; width: 100%; height: 320px; min-height: 120px;
  font: 13px/1.4 system-ui, -apple-system, 'Segoe UI', Roboto, sans-serif; }
:host([hidden]) { display: none; }
.box { position: absolute; inset: 0; overflow: auto; padding: 10px 14px; box-sizing: border-box; border-radius: 6px;
  background: #fff7ed; color: #7c2d12; border: 2px solid #f97316; }
p { margin: 6px 0 0; overflow-wrap: anywhere; }
a { color: #9a3412; }
button { font: inherit; padding: 2px 10px; border-radius: 4px; border: 1px solid #c2410c; background: #ffedd5;
  color: inherit; cursor: pointer; }
button:focus-visible { outline: 3px solid #2563eb; outline-offset: 2px; }
iframe { position: absolute; inset: 0; width: 100%; height: 100%; border: 0; }
@media (prefers-color-scheme: dark) {
  .box { background: #431407; color: #ffedd5; }
  a { color: #fdba74; }
  button { background: #7c2d12; border-color: #fdba74; }
}`;

  /** A constructed sheet, which a page's Content-Security-Policy allows without 'unsafe-inline'. */
  function appendStyles(root: ShadowRoot): void {
    if ('replaceSync' in CSSStyleSheet.prototype) {
      const sheet = new CSSStyleSheet();
      sheet.replaceSync(CSS);
      root.adoptedStyleSheets = [sheet];
    } else {
      const style = document.createElement('style');
      style.textContent = CSS;
      root.append(style);
    }
  }
})();
