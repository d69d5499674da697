/**
 * The teaching tools of a `<subdiv-viewer>` (attribute `tool`): the stencil
 * inspector, a basis function, split then smooth, the halfedge explorer
 * (its arrows; a click picks one) — the app's own classes
 * (web/teach/) over the element's SubdivViewer, driven by the attributes
 * `tool`, `vertex` and `split` instead of panels. A click on the view picks
 * a vertex as in the app and is reflected into `vertex`; what is shown is
 * told in the caption (embed-caption.ts) and by `stencil` and `basis`
 * events.
 */
import type { Mesh } from '../core/mesh';
import type { ViewClick } from '../render/scene-view';
import { BasisView } from '../teach/basis-view';
import { HalfedgeExplorer } from '../teach/halfedge-explorer';
import { SplitSmooth } from '../teach/split-smooth';
import { StencilInspector, stencilOrigin, stencilSum } from '../teach/stencil-inspector';
import { influenceEnds } from '../ui/influence-bar';
import type { SubdivViewer } from '../viewer/subdiv-viewer';
import type { CaptionContent, EmbedCaption } from './embed-caption';
import type { EmbedControls } from './embed-controls';
import type { BasisDetail, StencilDetail } from './embed-events';
import type { EmbedState, EmbedTool } from './embed-state';

/** What the tools need from their element. */
export interface ToolHost {
  /** The attributes as they read now. */
  readState(): EmbedState;
  /** The element is still bringing the viewer to its attributes (loading, stepping): wait. */
  settling(): boolean;
  /** Writes a picked vertex into the `vertex` attribute. */
  setVertex(vertex: number): void;
  /** Writes the split slider's value into the `split` attribute. */
  setSplit(t: number): void;
  /** Reports a tool's failed request (message and `error` event). */
  fail(error: unknown): void;
  dispatch(type: 'stencil', detail: StencilDetail): void;
  dispatch(type: 'basis', detail: BasisDetail): void;
}

export class EmbedTools {
  private readonly inspector: StencilInspector;
  private readonly basis: BasisView;
  private readonly split: SplitSmooth;
  private readonly halfedges: HalfedgeExplorer;
  private tool: EmbedTool = 'none';
  /** What was last asked of the tool (another level, model, vertex or t asks again). */
  private applied: { key: string; mesh: Mesh | null } | null = null;
  private lastStencil: unknown = null;
  private lastBasis: unknown = null;
  /** Play ran and its last frame is still to come. */
  private playing = false;
  private asking = false;

  constructor(
    private readonly viewer: SubdivViewer,
    private readonly host: ToolHost,
    private readonly caption: EmbedCaption,
    private readonly controls: EmbedControls,
  ) {
    const fail = (error: unknown) => host.fail(error);
    this.inspector = new StencilInspector(viewer, fail);
    this.basis = new BasisView(viewer, fail);
    this.split = new SplitSmooth(viewer, fail);
    this.halfedges = new HalfedgeExplorer(viewer, fail);
    this.halfedges.onChange(() => this.show());
    this.inspector.onChange((state) => {
      if (state.stencil && state.stencil !== this.lastStencil && this.tool === 'stencils') {
        const s = state.stencil;
        host.dispatch('stencil', {
          level: s.level,
          vertex: s.vertex,
          kind: s.kind,
          parents: s.parents.map((p) => ({ ...p })),
        });
      }
      this.lastStencil = state.stencil;
      this.show();
    });
    this.basis.onChange((state) => {
      const shown = state.shown;
      if (shown && shown !== this.lastBasis && this.tool === 'basis') {
        const { vertex, level, reached, count, max } = shown;
        host.dispatch('basis', { vertex, level, reached, count, max });
      }
      this.lastBasis = shown;
      this.show();
    });
    this.split.onChange((state) => {
      // Play reached the smoothed level (its last frame is drawn after the animation stopped): the attribute says so too.
      if (state.animating) this.playing = true;
      else if (this.playing && state.t === 1) {
        this.playing = false;
        if (this.tool === 'split') {
          this.applied = { key: this.splitKey(1), mesh: null };
          host.setSplit(1);
        }
      }
      this.show();
    });
    viewer.onChange(() => this.refresh());
    viewer.view.onClick = (click) => this.click(click);
  }

  /** Brings the tools to the attributes (`tool`, `vertex`, `split`) after one of them changed. */
  apply(): void {
    const { tool } = this.host.readState();
    if (tool !== this.tool) {
      this.switchOff(this.tool);
      this.tool = tool;
      this.applied = null;
      if (tool === 'stencils') this.inspector.setInspecting(true);
      if (tool === 'halfedges') this.halfedges.setExploring(true);
    }
    this.refresh();
  }

  /** Plays the step from the split to the smoothed level (tool="split"). */
  play(): void {
    if (this.tool === 'split') this.split.animate();
  }

  /** Asks the tool for what the attributes name, once the viewer shows what they ask. */
  refresh(): void {
    const want = this.host.readState();
    const state = this.viewer.state;
    const busy = state.busy?.kind === 'load' || state.busy?.kind === 'subdivide';
    // Not again from the viewer's changes that asking makes (BasisView shows the control mesh).
    if (this.tool !== 'none' && state.levelCount > 0 && !busy && !this.host.settling() && !this.asking) {
      this.asking = true;
      try {
        if (this.tool === 'stencils') this.askStencil(want.vertex);
        else if (this.tool === 'basis') this.askBasis(want.vertex);
        else if (this.tool === 'split') this.askSplit(want.split);
      } finally {
        this.asking = false;
      }
    }
    this.show();
  }

  private askStencil(vertex: number | null): void {
    const key = `stencils ${this.viewer.levelId()} ${vertex}`;
    if (this.applied?.key === key) return;
    this.applied = { key, mesh: null };
    // The marks of the vertex before go first (a number out of range would leave them).
    this.inspector.setInspecting(false);
    this.inspector.setInspecting(true);
    if (vertex !== null) void this.inspector.select(vertex);
  }

  private askBasis(vertex: number | null): void {
    // BasisView colours each level as it is shown; only another model or vertex asks again.
    const key = `basis ${vertex}`;
    const mesh = this.viewer.controlMesh;
    if (this.applied?.key === key && this.applied.mesh === mesh) return;
    this.applied = { key, mesh };
    this.basis.setPicking(false);
    this.pickBasis();
    if (vertex !== null) void this.basis.select(vertex);
  }

  private askSplit(t: number): void {
    const available = this.split.state.available;
    const key = this.splitKey(t);
    if (this.applied?.key === key || !available) return;
    this.applied = { key, mesh: null };
    this.playing = false;
    // A level is drawn at its own points (t = 1) until asked otherwise: nothing to fetch.
    if (t !== 1 || this.split.state.t !== 1) void this.split.setT(t);
  }

  private splitKey(t: number): string {
    return `split ${this.viewer.levelId()} ${t}`;
  }

  /** The basis view picking, with the control mesh as the attributes have it (BasisView shows it). */
  private pickBasis(): void {
    const control = this.viewer.state.overlays.control;
    this.basis.setPicking(true);
    if (!control) this.viewer.setOverlay('control', false);
  }

  /** Turns `tool` off: its marks, colours or blend go. */
  private switchOff(tool: EmbedTool): void {
    if (tool === 'stencils') this.inspector.setInspecting(false);
    if (tool === 'halfedges') this.halfedges.setExploring(false);
    if (tool === 'basis') this.basis.setPicking(false);
    if (tool === 'split') {
      const s = this.split.state;
      if (s.t !== 1 || s.animating) void this.split.setT(1);
    }
  }

  private click(click: ViewClick): void {
    if (this.tool === 'halfedges') this.halfedges.click(click);
    const vertex =
      this.tool === 'stencils' ? this.inspector.pick(click) : this.tool === 'basis' ? this.basis.pick(click) : null;
    if (vertex !== null) this.host.setVertex(vertex);
  }

  /** The caption and the split controls for the tool's state. */
  private show(): void {
    this.controls.updateSplit(this.tool === 'split' ? this.split.state : null);
    this.caption.show(this.content());
  }

  private content(): CaptionContent | null {
    const want = this.host.readState();
    const level = this.viewer.state.level;
    switch (this.tool) {
      case 'none':
        return null;
      case 'stencils': {
        const state = this.inspector.state;
        const s = state.stencil;
        if (state.problem) return { line: state.problem, hint: true };
        if (!s || s.vertex !== want.vertex) {
          // While the levels asked for are computed, what is coming, not what to do at level 0.
          const coming = this.host.settling() || this.viewer.state.levelCount === 0;
          if (want.vertex !== null && (coming || level >= 1))
            return { line: `Level ${coming ? want.levels : level}, vertex ${want.vertex}…`, hint: true };
          if (level < 1 && !coming)
            return { line: 'Level 0 is the control mesh: go to level 1 or higher, then click a vertex.', hint: true };
          return { line: 'Click a vertex of the surface to see the weights that place it.', hint: true };
        }
        const { of, size } = stencilOrigin(s);
        const what = `${s.kind}${of ? ` of ${of}` : ''}${size ? ` (${size})` : ''}`;
        const note = `v: vertices of level ${s.level - 1}${s.formula ? ` · ${s.formula}` : ''}`;
        return { line: `Level ${s.level}, vertex ${s.vertex}: ${what} = ${stencilSum(s)}`, note };
      }
      case 'basis': {
        const state = this.basis.state;
        const shown = state.shown;
        if (state.problem) return { line: state.problem, hint: true };
        if (!shown || shown.vertex !== want.vertex) {
          if (want.vertex !== null) return { line: `Basis function of control vertex ${want.vertex}…`, hint: true };
          return {
            line: 'Click a vertex of the control mesh to colour the surface by its basis function.',
            hint: true,
          };
        }
        return {
          line: `Basis function of control vertex ${shown.vertex}: reaches ${shown.reached} of ${shown.count} vertices`,
          legend: influenceEnds(shown.min, shown.max),
        };
      }
      case 'split': {
        const state = this.split.state;
        if (state.message) return { line: state.message, hint: true };
        return { line: `Split → smoothed: ${state.t.toFixed(2)}` };
      }
      case 'halfedges': {
        const state = this.halfedges.state;
        if (state.refusal) return { line: state.refusal, hint: true };
        const p = state.picked;
        if (!p) {
          if (state.halfedgeCount === 0) return { line: 'Halfedges…', hint: true };
          return { line: `Level ${level}: ${state.halfedgeCount} halfedges. Click an arrow to pick one.`, hint: true };
        }
        const face = p.face < 0 ? 'border' : `face ${p.face}`;
        return {
          line: `Halfedge ${p.h}: vertex ${p.source} → vertex ${p.target}, ${face}; next ${p.next}, prev ${p.prev}, opposite ${p.opposite}`,
          note: 'Numbered as CGAL’s Surface_mesh numbers this level (subdiv halfedges prints the table)',
        };
      }
    }
  }
}
