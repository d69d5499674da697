/**
 * embed.html: one `<subdiv-viewer>` filling the page, started from the
 * query (`?src=…&scheme=…&levels=…&mode=…&view=…&controls=…&tool=…&beside=…`), for learning
 * platforms that accept only iframes. It posts the element's events to the
 * parent page and takes commands from it (embed-messages.ts).
 */
import { parseViewerParams } from '../viewer/viewer-params';
import { checkCommand, type EmbedEventMessage, type EmbedEventName } from './embed-messages';
import { attributesOfParams } from './embed-state';
import { SubdivViewerElement } from './subdiv-viewer-element';

if (!customElements.get('subdiv-viewer')) customElements.define('subdiv-viewer', SubdivViewerElement);

const query = new URLSearchParams(window.location.search);
const { params, problems } = parseViewerParams(query);
const viewer = document.createElement('subdiv-viewer');
for (const [name, value] of attributesOfParams(params)) viewer.setAttribute(name, value);
if (!params.controls) viewer.setAttribute('controls', 'minimal');
// Read by the element, which names a bad value in an `error` event (posted to the parent).
for (const key of ['alt', 'background', 'tool', 'vertex', 'split', 'distance']) {
  const value = query.get(key);
  if (value !== null) viewer.setAttribute(key, value);
}
// The page is the viewer alone; styled here, as the site's policy refuses inline styles.
for (const element of [document.documentElement, document.body])
  element.style.cssText = 'margin:0;height:100%;overflow:hidden';
viewer.style.cssText = 'position:fixed;inset:0;width:100%;height:100%;border-radius:0';
document.body.append(viewer);

function post(name: EmbedEventName, detail: object): void {
  if (window.parent === window) return;
  // The facts of a public mesh: nothing secret, and the parent's origin is not known in advance.
  window.parent.postMessage({ subdivlab: name, ...detail } satisfies EmbedEventMessage, '*');
}

for (const name of ['load', 'level-change', 'error', 'progress', 'stencil', 'basis', 'distance'] as const) {
  viewer.addEventListener(name, (event) => post(name, (event as CustomEvent).detail ?? {}));
}
for (const problem of problems) post('error', { code: 'invalid_argument', message: problem, line: 0, source: 'query' });

window.addEventListener('message', (event: MessageEvent) => {
  if (event.source !== window.parent || window.parent === window) return;
  const checked = checkCommand(event.data);
  if (!checked.ok) {
    console.warn(`[subdivlab] ignored a message: ${checked.reason}`);
    return;
  }
  const command = checked.command;
  switch (command.subdivlab) {
    case 'load':
      if (!('src' in command)) void viewer.load(command.text, command.name).catch(() => undefined);
      else if (command.src === viewer.src) void viewer.reload();
      else viewer.src = command.src;
      break;
    case 'set-scheme':
      viewer.scheme = command.scheme;
      break;
    case 'subdivide':
      void viewer.subdivide();
      break;
    case 'set-level':
      void viewer.setLevel(command.level);
      break;
    case 'set-view':
      viewer.setView(command.view);
      break;
    case 'set-render-mode':
      viewer.renderMode = command.mode;
      break;
    case 'set-overlay':
      if (command.on) viewer.setAttribute(command.overlay, '');
      else viewer.removeAttribute(command.overlay);
      break;
    case 'set-triangulate':
      viewer.triangulate = command.on;
      break;
    case 'set-tool':
      // The vertex first: the tool then starts on it.
      if (command.vertex !== undefined) viewer.vertex = command.vertex;
      viewer.tool = command.tool;
      break;
    case 'set-split':
      viewer.split = command.t;
      break;
  }
});

post('ready', { version: 1 });
