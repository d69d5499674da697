/** Colours shared by the WebGL view and the figures (SVG, PDF, EPS). */
import { SURFACE_COLORS } from './surface-materials';

export const VIEW_COLORS = {
  background: '#f3f4f6',
  /** Behind the model when the page prefers a dark scheme (the element's default there). */
  backgroundDark: '#1f2328',
  surface: SURFACE_COLORS.front,
  edges: '#1f2d3d',
  edgesOnDark: '#dce3ea',
  control: '#e8590c',
  curves: '#c2255c',
  /** Border edges (of one face), drawn wider with the polygon edges. */
  border: '#2f9e44',
  bbox: '#6b7280',
  /** The control edges and vertex the crease editor has selected, and the vertex the stencil inspector shows. */
  selection: '#15aabf',
  /** The parents of that vertex in the stencil inspector. */
  parents: '#e8590c',
} as const;
