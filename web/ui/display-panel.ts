/** Render mode menu, overlay toggles, and the view buttons (fit, save, restore). */

import { type OverlayName, RENDER_MODES, type RenderMode } from '../render/render-mode';
import type { ViewerState } from '../viewer/subdiv-viewer';
import { button, el, section, uniqueId } from './dom';

export interface DisplayPanelHandlers {
  onRenderMode: (mode: RenderMode) => void;
  onOverlay: (name: OverlayName, visible: boolean) => void;
  onFit: () => void;
  onSaveView: () => void;
  onRestoreView: () => void;
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
  private readonly restore: HTMLButtonElement;

  constructor(handlers: DisplayPanelHandlers) {
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
    this.restore = button('Restore view', 'view.restore', handlers.onRestoreView, 'Go back to the saved viewpoint');
    this.element = section(
      'Display',
      'display-panel',
      el('label', { attrs: { for: modeId }, text: 'Render mode (R)' }),
      this.mode,
      ...toggles,
      el(
        'div',
        { className: 'row wrap' },
        button('Fit view', 'view.fit', handlers.onFit, 'Show the whole model (F)'),
        button('Save view', 'view.save', handlers.onSaveView, 'Remember this viewpoint, also for other models'),
        this.restore,
      ),
    );
  }

  update(state: ViewerState, hasSavedView: boolean): void {
    this.mode.value = state.renderMode;
    for (const [name, input] of this.toggles) input.checked = state.overlays[name];
    for (const [name, input] of this.toggles) input.disabled = !overlayAvailable(name, state);
    this.restore.disabled = !hasSavedView;
  }
}
