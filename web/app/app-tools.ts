/**
 * The app's tools around the viewer, each with its panel: crease editing,
 * the stencil inspector, the basis function view, split then smooth, side
 * by side (its panes around the app's view), Inspect, the result check and
 * the halfedge explorer with its Euler operators;
 * which of them a click on the view picks for. The shell places the panels
 * and the panes and gives the tools what they need of it (ToolsHost).
 */

import type { SchemeName } from '../core/mesh';
import { CreaseEditor } from '../edit/crease-editor';
import { MeshInspector } from '../inspect/mesh-inspector';
import { BasisView } from '../teach/basis-view';
import { EulerSteps } from '../teach/euler-steps';
import { HalfedgeExplorer } from '../teach/halfedge-explorer';
import { ResultCheck } from '../teach/result-check';
import { SideBySide } from '../teach/side-by-side';
import { SplitSmooth } from '../teach/split-smooth';
import { StencilInspector } from '../teach/stencil-inspector';
import { BasisPanel } from '../ui/basis-panel';
import { CheckPanel } from '../ui/check-panel';
import { CreasePanel } from '../ui/crease-panel';
import { EulerPanel } from '../ui/euler-panel';
import { HalfedgePanel } from '../ui/halfedge-panel';
import { InspectPanel } from '../ui/inspect-panel';
import { PaneGrid } from '../ui/pane-grid';
import { SidePanel } from '../ui/side-panel';
import { SplitPanel } from '../ui/split-panel';
import { StencilPanel } from '../ui/stencil-panel';
import { handleViewKey } from '../ui/view-keys';
import { type LargeStepInfo, SubdivViewer } from '../viewer/subdiv-viewer';

/** What the tools need of the app shell. */
export interface ToolsHost {
  readonly viewer: SubdivViewer;
  /** The app's view, which side by side puts panes beside. */
  readonly stage: HTMLElement;
  /** Shows an error about the shown model. */
  modelError(error: unknown): void;
  /** Computes the levels up to `level` and shows it; false when a step failed or was declined. */
  reachLevel(level: number): Promise<boolean>;
  /** Asks before a step larger than the tab should hold (of `scheme`, in a pane). */
  confirmLargeStep(info: LargeStepInfo, scheme: SchemeName): Promise<boolean>;
}

/** What a click on the view picks for: the crease editor, the stencil inspector, the basis view, the halfedge explorer, or none. */
export type ClickMode = 'creases' | 'inspect' | 'basis' | 'halfedges' | null;

export class AppTools {
  readonly creaseEditor: CreaseEditor;
  readonly inspector: StencilInspector;
  readonly sideBySide: SideBySide;
  readonly paneGrid: PaneGrid;
  private readonly creasePanel: CreasePanel;
  private readonly stencilPanel: StencilPanel;
  private readonly basis: BasisView;
  private readonly basisPanel: BasisPanel;
  private readonly split: SplitSmooth;
  private readonly splitPanel: SplitPanel;
  private readonly sidePanel: SidePanel;
  private readonly inspector3d: MeshInspector;
  private readonly inspectPanel: InspectPanel;
  private readonly resultCheck: ResultCheck;
  private readonly checkPanel: CheckPanel;
  readonly halfedges: HalfedgeExplorer;
  readonly euler: EulerSteps;
  private readonly halfedgePanel: HalfedgePanel;

  constructor(private readonly host: ToolsHost) {
    this.creaseEditor = new CreaseEditor(this.host.viewer, (error) => this.host.modelError(error));
    this.inspector = new StencilInspector(this.host.viewer, (error) => this.host.modelError(error));
    this.stencilPanel = new StencilPanel({
      onInspecting: (on) => this.setClickMode(on ? 'inspect' : null),
      onVertex: (vertex) => void this.inspector.select(vertex),
    });
    this.inspector.onChange((state) => this.stencilPanel.update(state));
    this.stencilPanel.update(this.inspector.state);
    this.basis = new BasisView(this.host.viewer, (error) => this.host.modelError(error));
    this.basisPanel = new BasisPanel({
      onPicking: (on) => this.setClickMode(on ? 'basis' : null),
      onVertex: (vertex) => void this.basis.select(vertex),
    });
    this.basis.onChange((state) => this.basisPanel.update(state));
    this.basisPanel.update(this.basis.state);
    this.split = new SplitSmooth(this.host.viewer, (error) => this.host.modelError(error));
    this.splitPanel = new SplitPanel({
      onT: (t) => void this.split.setT(t),
      onAnimate: () => this.split.animate(),
    });
    this.split.onChange((state) => this.splitPanel.update(state));
    this.splitPanel.update(this.split.state);
    this.paneGrid = new PaneGrid(host.stage, {
      onScheme: (index, scheme) => this.sideBySide.setScheme(index, scheme),
      onStep: (index, delta) => this.sideBySide.step(index, delta),
      onKey: (index, event) => {
        const viewer = this.sideBySide.viewer(index);
        if (viewer) handleViewKey(viewer.view, event);
      },
    });
    this.sideBySide = new SideBySide(
      this.host.viewer,
      {
        addPane: (index) => {
          const pane: SubdivViewer = new SubdivViewer(this.paneGrid.add(index), {
            confirmLargeStep: (info) => this.host.confirmLargeStep(info, pane.state.scheme),
          });
          return pane;
        },
        removePane: (index) => this.paneGrid.remove(index),
      },
      (error) => this.host.modelError(error),
    );
    this.sidePanel = new SidePanel({
      onCount: (count) => this.sideBySide.setCount(count),
      onTogether: (together) => this.sideBySide.setTogether(together),
      onPair: (a, b) => this.sideBySide.setPair(a, b),
      onColours: (on) => this.sideBySide.setColours(on),
    });
    this.sideBySide.onChange((state) => {
      this.sidePanel.update(state, this.host.viewer.state.levelCount > 0);
      this.paneGrid.update(state);
    });
    this.sidePanel.update(this.sideBySide.state, false);
    this.inspector3d = new MeshInspector(this.host.viewer, (error) => this.host.modelError(error));
    this.inspectPanel = new InspectPanel({
      onChoice: (choice, layer, on) => void this.inspector3d.show(choice, layer, on),
      onInspect: () => void this.inspector3d.inspect(),
      onFrame: (pair) => this.inspector3d.frame(pair),
    });
    this.inspector3d.onChange((state) => this.inspectPanel.update(state));
    this.inspectPanel.update(this.inspector3d.state);
    this.resultCheck = new ResultCheck(
      this.host.viewer,
      (level) => this.host.reachLevel(level),
      (error) => this.host.modelError(error),
    );
    this.checkPanel = new CheckPanel({
      onCheck: (name, text, format, level, tolerance) =>
        void this.resultCheck.check(name, text, format, level, tolerance),
      onShowStencil: (level, vertex) => {
        this.host.viewer.setLevel(level);
        this.setClickMode('inspect');
        void this.inspector.select(vertex);
      },
    });
    this.resultCheck.onChange((state) => this.checkPanel.update(state));
    this.checkPanel.update(this.resultCheck.state);
    this.halfedges = new HalfedgeExplorer(this.host.viewer, (error) => this.host.modelError(error));
    this.euler = new EulerSteps(this.host.viewer, this.halfedges, (error) => this.host.modelError(error));
    const eulerPanel = new EulerPanel({
      onChooseSecond: (on) => this.halfedges.chooseSecond(on),
      onOperator: (op) => void this.euler.apply(op),
      onUndo: () => void this.euler.undo(),
      onStep: () => void this.euler.step(),
      onPlay: (play) => (play ? void this.euler.play() : this.euler.stop()),
    });
    this.halfedgePanel = new HalfedgePanel(
      {
        onExploring: (on) => this.setClickMode(on ? 'halfedges' : null),
        onHalfedge: (h) => this.halfedges.select(h),
        onMove: (move) => this.halfedges.move(move),
        onCirculate: (kind) => this.halfedges.circulate(kind),
      },
      eulerPanel,
    );
    const showHalfedges = () => {
      const state = this.halfedges.state;
      this.halfedgePanel.update(state);
      eulerPanel.update(this.euler.state, state.picked !== null, state.choosingSecond, state.second);
    };
    this.halfedges.onChange(showHalfedges);
    this.euler.onChange(showHalfedges);
    showHalfedges();
    // A click on the view picks for the crease editor, the inspector or the basis view, whichever is on.
    this.host.viewer.view.onClick = (click) => {
      this.creaseEditor.click(click);
      this.inspector.click(click);
      this.basis.click(click);
      this.halfedges.click(click);
    };
    this.creasePanel = new CreasePanel({
      onEditing: (on) => this.setClickMode(on ? 'creases' : null),
      onSharpness: (sharpness) => void this.creaseEditor.setSharpness(sharpness),
      onUndo: () => this.creaseEditor.undo(),
      onRedo: () => this.creaseEditor.redo(),
    });
    this.creaseEditor.onChange((state) => this.creasePanel.update(state));
    this.creasePanel.update(this.creaseEditor.state);
  }

  /** The tools' panels, in the sidebar's order. */
  get panels(): HTMLElement[] {
    return [
      this.sidePanel.element,
      this.creasePanel.element,
      this.stencilPanel.element,
      this.basisPanel.element,
      this.halfedgePanel.element,
      this.splitPanel.element,
      this.checkPanel.element,
      this.inspectPanel.element,
    ];
  }

  /** What a click on the view picks for: one tool at a time. */
  setClickMode(mode: ClickMode): void {
    // The one going off first, so that its marks go before the other's come.
    if (mode !== 'creases') this.creaseEditor.setEditing(false);
    if (mode !== 'inspect') this.inspector.setInspecting(false);
    if (mode !== 'basis') this.basis.setPicking(false);
    if (mode !== 'halfedges') this.halfedges.setExploring(false);
    if (mode === 'creases') this.creaseEditor.setEditing(true);
    if (mode === 'inspect') this.inspector.setInspecting(true);
    if (mode === 'basis') this.basis.setPicking(true);
    if (mode === 'halfedges') this.halfedges.setExploring(true);
    // A tool turned on by a key or from another panel (Check's stencil buttons): its panel comes into sight.
    const panel =
      mode &&
      {
        creases: this.creasePanel,
        inspect: this.stencilPanel,
        basis: this.basisPanel,
        halfedges: this.halfedgePanel,
      }[mode];
    panel?.element.scrollIntoView({ block: 'nearest' });
  }
}
