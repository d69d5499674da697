/**
 * The attributes of `<subdiv-viewer>` as typed properties, reflected both
 * ways (a property writes its attribute; the element reacts to attributes
 * only). Reading goes through embed-state.ts, so a bad attribute reads as
 * its default.
 */
import type { SchemeName } from '../core/mesh';
import { OVERLAY_DEFAULTS, type RenderMode } from '../render/render-mode';
import { type ControlsMode, OVERLAY_KEYS } from '../viewer/viewer-params';
import { type EmbedState, type EmbedTool, readEmbedState } from './embed-state';

/** Every attribute of the element and the property that reflects it. */
const PROPERTIES = {
  src: 'src',
  scheme: 'scheme',
  levels: 'levels',
  'render-mode': 'renderMode',
  'control-mesh': 'controlMesh',
  'control-edges': 'controlEdges',
  bbox: 'bbox',
  creases: 'creases',
  triangulate: 'triangulate',
  rules: 'rules',
  view: 'view',
  controls: 'controls',
  alt: 'alt',
  background: 'background',
  tool: 'tool',
  vertex: 'vertex',
  split: 'split',
  beside: 'beside',
  distance: 'distance',
  'line-width': 'lineWidth',
} as const;

/** The attributes the element observes. */
export const OBSERVED_ATTRIBUTES = Object.keys(PROPERTIES) as (keyof typeof PROPERTIES)[];

export class ViewerAttributes extends HTMLElement {
  get src(): string {
    return this.getAttribute('src') ?? '';
  }
  set src(value: string) {
    this.setAttribute('src', value);
  }
  get scheme(): SchemeName {
    return this.readState().scheme;
  }
  set scheme(value: SchemeName) {
    this.setAttribute('scheme', value);
  }
  /** The level asked for (and, once computed, shown). */
  get levels(): number {
    return this.readState().levels;
  }
  set levels(value: number) {
    this.setAttribute('levels', String(value));
  }
  get renderMode(): RenderMode {
    return this.readState().renderMode;
  }
  set renderMode(value: RenderMode) {
    this.setAttribute('render-mode', value);
  }
  get controlMesh(): boolean {
    return this.readState().overlays.control;
  }
  set controlMesh(on: boolean) {
    this.setFlag('control-mesh', on);
  }
  get controlEdges(): boolean {
    return this.readState().overlays.curves;
  }
  set controlEdges(on: boolean) {
    this.setFlag('control-edges', on);
  }
  get bbox(): boolean {
    return this.readState().overlays.bbox;
  }
  set bbox(on: boolean) {
    this.setFlag('bbox', on);
  }
  /** The level's creases and corners (OpenSubdiv's tags): on unless `creases="0"`. */
  get creases(): boolean {
    return this.readState().overlays.creases;
  }
  set creases(on: boolean) {
    this.setFlag('creases', on);
  }
  get triangulate(): boolean {
    return this.readState().triangulate;
  }
  set triangulate(on: boolean) {
    this.setFlag('triangulate', on);
  }
  get rules(): string {
    return this.getAttribute('rules') ?? '';
  }
  set rules(value: string) {
    this.setAttribute('rules', value);
  }
  get view(): string {
    return this.getAttribute('view') ?? '';
  }
  set view(value: string) {
    this.setAttribute('view', value);
  }
  get controls(): ControlsMode {
    return this.readState().controls;
  }
  set controls(value: ControlsMode) {
    this.setAttribute('controls', value);
  }
  get alt(): string {
    return this.getAttribute('alt') ?? '';
  }
  set alt(value: string) {
    this.setAttribute('alt', value);
  }
  get background(): string {
    return this.getAttribute('background') ?? '';
  }
  set background(value: string) {
    this.setAttribute('background', value);
  }
  /** The teaching tool shown: `none`, `stencils`, `basis`, `split` or `halfedges`. */
  get tool(): EmbedTool {
    return this.readState().tool;
  }
  set tool(value: EmbedTool) {
    this.setAttribute('tool', value);
  }
  /** The vertex the tool shows (null: none; set null to remove the attribute). */
  get vertex(): number | null {
    return this.readState().vertex;
  }
  set vertex(value: number | null) {
    if (value === null) this.removeAttribute('vertex');
    else this.setAttribute('vertex', String(value));
  }
  /** Schemes shown side by side in panes beside this one (set an empty list to remove the attribute). */
  get beside(): SchemeName[] {
    return this.readState().beside;
  }
  set beside(value: readonly SchemeName[] | string) {
    const text = typeof value === 'string' ? value : value.join(' ');
    if (text.trim() === '') this.removeAttribute('beside');
    else this.setAttribute('beside', text);
  }
  /** Side by side: the Hausdorff distance of the first two panes and their colours by it (on unless distance="0"). */
  get distance(): boolean {
    return this.readState().distance;
  }
  set distance(value: boolean) {
    this.setAttribute('distance', value ? '1' : '0');
  }
  /** Split, then smooth: 0 (the split alone) to 1 (the smoothed level). */
  get split(): number {
    return this.readState().split;
  }
  set split(value: number) {
    this.setAttribute('split', String(value));
  }
  /** Width of the drawn lines in CSS pixels (a ×4 PNG's are four times as wide). */
  get lineWidth(): number {
    return this.readState().lineWidth;
  }
  set lineWidth(value: number) {
    this.setAttribute('line-width', String(value));
  }

  /**
   * Re-applies properties a page set before the element was defined (they
   * were stored on the plain element and would hide these accessors).
   */
  protected upgradeProperties(): void {
    for (const name of Object.values(PROPERTIES)) {
      if (!Object.hasOwn(this, name)) continue;
      const value = (this as unknown as Record<string, unknown>)[name];
      delete (this as unknown as Record<string, unknown>)[name];
      (this as unknown as Record<string, unknown>)[name] = value;
    }
  }

  protected readState(): EmbedState {
    return readEmbedState((name) => this.getAttribute(name));
  }

  /**
   * A boolean attribute: absent in its default state, else present when on
   * and "0" when off (the creases overlay is on by default).
   */
  protected setFlag(name: string, on: boolean): void {
    const absent = name === OVERLAY_KEYS.creases ? OVERLAY_DEFAULTS.creases : false;
    if (on === absent) this.removeAttribute(name);
    else this.setAttribute(name, on ? '' : '0');
  }
}
