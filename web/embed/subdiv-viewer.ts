/**
 * The `<subdiv-viewer>` module: import it once on a page and write
 * `<subdiv-viewer src="meshes/torus.off" scheme="loop" levels="2"></subdiv-viewer>`.
 * Built to dist/embed/subdiv-viewer.js with its worker and `.wasm` beside it.
 */
import { SubdivViewerElement } from './subdiv-viewer-element';

export type {
  BasisDetail,
  ErrorDetail,
  LevelChangeDetail,
  LoadDetail,
  ProgressDetail,
  StencilDetail,
} from './embed-events';
export type { EmbedTool } from './embed-state';
export { SubdivViewerElement };

if (!customElements.get('subdiv-viewer')) customElements.define('subdiv-viewer', SubdivViewerElement);

declare global {
  interface HTMLElementTagNameMap {
    'subdiv-viewer': SubdivViewerElement;
  }
}
