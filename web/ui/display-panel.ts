/** Render mode menu, overlay toggles, and the view's own controls (view-controls.ts) below them. */

import { type OverlayName, RENDER_MODES, type RenderMode } from '../render/render-mode';
import type { ViewerState } from '../viewer/subdiv-viewer';
import { el, section, uniqueId } from './dom';

export interface DisplayPanelHandlers {
  onRenderMode: (mode: RenderMode) => void;
  onOverlay: (name: OverlayName, visible: boolean) => void;
}

/** Overlay toggles in display order. */
const OVERLAYS: readonly { name: OverlayName; label: string; key: string }[] = [
  { name: 'control', label: 'Control mesh (level 0 edges)', key: 'c' },
  { name: 'bbox', label: 'Bounding box', key: 'b' },
  { name: 'curves', label: 'Control-edge curves', key: 'e' },
  { name: 'creases', label: 'Creases and corners', key: 'k' },
];

/**
 * Whether overlay `name` can be switched on for `state`: the curves exist
 * only where the core marked control edges (primal schemes), the creases
 * where the shown level has sharp edges or corners.
 */
export function overlayAvailable(name: OverlayName, state: ViewerState): boolean {
  if (name === 'creases') return state.tags !== null && state.tags.creases + state.tags.corners > 0;
  if (name !== 'curves') return true;
  return state.facts !== null && state.facts.controlEdges > 0;
}

export class DisplayPanel {
  readonly element: HTMLElement;
  private readonly mode: HTMLSelectElement;
  private readonly toggles = new Map<OverlayName, HTMLInputElement>();

  /** `viewControls`: the view's buttons and settings, below the toggles. */
  constructor(handlers: DisplayPanelHandlers, viewControls: Node) {
    const modeId = uniqueId('render-mode');
    this.mode = el('select', { testId: 'controls.render-mode', attrs: { id: modeId, 'aria-keyshortcuts': 'r' } });
    for (const { mode, label } of RENDER_MODES) this.mode.append(el('option', { text: label, attrs: { value: mode } }));
    this.mode.addEventListener('change', () => handlers.onRenderMode(this.mode.value as RenderMode));
    const toggles = OVERLAYS.map(({ name, label, key }) => {
      const id = uniqueId(`overlay-${name}`);
      const input = el('input', {
        testId: `controls.overlay-${name}`,
        attrs: { type: 'checkbox', id, 'aria-keyshortcuts': key },
      });
      input.addEventListener('change', () => handlers.onOverlay(name, input.checked));
      this.toggles.set(name, input);
      return el('label', { className: 'check', attrs: { for: id } }, input, ` ${label} (${key.toUpperCase()})`);
    });
    this.element = section(
      'Display',
      'display-panel',
      el('label', { attrs: { for: modeId }, text: 'Render mode (R)' }),
      this.mode,
      ...toggles,
      viewControls,
    );
  }

  update(state: ViewerState): void {
    this.mode.value = state.renderMode;
    for (const [name, input] of this.toggles) input.checked = state.overlays[name];
    for (const [name, input] of this.toggles) input.disabled = !overlayAvailable(name, state);
  }
}
