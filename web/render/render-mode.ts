/** How the surface is drawn. Overlays (control mesh, bounding box) are separate toggles. */
export type RenderMode = 'smooth' | 'flat' | 'edges' | 'wireframe' | 'zebra' | 'mean-curvature' | 'gaussian-curvature';

/** The modes in menu and `r`-cycling order, with their labels. */
export const RENDER_MODES: readonly { mode: RenderMode; label: string }[] = [
  { mode: 'smooth', label: 'Smooth shaded' },
  { mode: 'flat', label: 'Flat shaded' },
  { mode: 'edges', label: 'Shaded with polygon edges' },
  { mode: 'wireframe', label: 'Wireframe (polygon edges)' },
  { mode: 'zebra', label: 'Reflection lines (zebra)' },
  { mode: 'mean-curvature', label: 'Mean curvature (colours)' },
  { mode: 'gaussian-curvature', label: 'Gaussian curvature (colours)' },
];

/** The mode after `mode` in cycling order. */
export function nextRenderMode(mode: RenderMode): RenderMode {
  const i = RENDER_MODES.findIndex((m) => m.mode === mode);
  return RENDER_MODES[(i + 1) % RENDER_MODES.length].mode;
}

/**
 * Overlays drawn with the surface: the level-0 edges, the bounding box, the
 * control-edge curves (edges of the shown level that lie on level-0 edges,
 * as the core marks them for primal schemes), and the shown level's sharp
 * edges and corners (OpenSubdiv's tags), coloured by sharpness.
 */
export type OverlayName = 'control' | 'bbox' | 'curves' | 'creases';

/** All overlays, in display order. */
export const OVERLAY_NAMES: readonly OverlayName[] = ['control', 'bbox', 'curves', 'creases'];

/**
 * Each overlay when nothing says otherwise: a tagged file's creases are
 * what its author wants seen, so they show until switched off; the others
 * wait to be switched on. Links and attributes name an overlay only when
 * it differs from this.
 */
export const OVERLAY_DEFAULTS: Readonly<Record<OverlayName, boolean>> = {
  control: false,
  bbox: false,
  curves: false,
  creases: true,
};
