/**
 * The three.js side of one viewer: its canvas, scene, camera, trackball
 * controls, the surface of the shown level, its polygon edges and the
 * overlays. It draws on demand (when the camera or content changes) through
 * the page's one shared renderer, so many views can share a page.
 * Geometry comes in as LevelGraphics, owned by the caller; this class owns
 * only its materials and helper objects.
 */
import {
  Box3,
  Box3Helper,
  BufferGeometry,
  Color,
  Float32BufferAttribute,
  Mesh,
  type Object3D,
  PerspectiveCamera,
  Points,
  PointsMaterial,
  Scene,
  Sphere,
  Vector3,
} from 'three';
import { LineMaterial } from 'three/addons/lines/LineMaterial.js';
import { LineSegments2 } from 'three/addons/lines/LineSegments2.js';
import { LineSegmentsGeometry } from 'three/addons/lines/LineSegmentsGeometry.js';
import { CSS2DObject, CSS2DRenderer } from 'three/addons/renderers/CSS2DRenderer.js';
import { orbitCamera, panCamera, zoomCamera } from './camera-moves';
import { ClientMapping } from './client-mapping';
import { DEFAULT_VIEW_DIRECTION, fitCamera, fitDistance, freeRect, viewOffsetPixels } from './fit';
import { type LevelGraphics, showParts } from './level-graphics';
import { MappedTrackballControls } from './mapped-trackball-controls';
import { type Pick, pickElement, screenPointOf } from './pick';
import { OVERLAY_DEFAULTS, type OverlayName, type RenderMode } from './render-mode';
import { type SharedRenderer, sharedRenderer } from './shared-renderer';
import { addLights, SurfaceMaterials } from './surface-materials';
import { VIEW_COLORS } from './view-colors';
import { ViewLines } from './view-lines';
import type { ViewState } from './view-state';

export { VIEW_COLORS } from './view-colors';

/** A click on the view: its own CSS pixels from its top left (whatever transforms the page applies), and the modifier keys held. */
export interface ViewClick {
  x: number;
  y: number;
  altKey: boolean;
  shiftKey: boolean;
}

/** A press and release this close (pixels of the screen) is a click, not a drag of the camera. */
const CLICK_SLOP = 4;

export class SceneView {
  readonly canvas: HTMLCanvasElement;
  readonly camera: PerspectiveCamera;
  private readonly renderer: SharedRenderer;
  private readonly context: CanvasRenderingContext2D;
  private readonly detach: () => void;
  /** Clear colour of the view (null: transparent). */
  private background: string | null = VIEW_COLORS.background;
  private readonly scene = new Scene();
  private readonly controls: MappedTrackballControls;
  /** The page's pixels ↔ the view's own, under any CSS transform or zoom (a scaled slide). */
  private readonly mapping: ClientMapping;
  private readonly surface: Mesh;
  /** The polygon edges, the cage and the marked curves: fat lines (WebGL's own are one pixel wide). */
  private readonly lines = new ViewLines(VIEW_COLORS);
  private readonly creaseLines: LineSegments2;
  private readonly borderLines: LineSegments2;
  private readonly cornerPoints: Points<BufferGeometry, PointsMaterial>;
  private readonly selectedLines: LineSegments2;
  private readonly selectedPoints: Points<BufferGeometry, PointsMaterial>;
  /** The stencil inspector's parents (points) and their weights (labels over the canvas). */
  private readonly parentPoints: Points<BufferGeometry, PointsMaterial>;
  /** Thin lines from the inspected vertex to each parent. */
  private readonly parentLines: LineSegments2;
  /** Where the target is drawn (NDC), so the model clears the panels over the view: set by {@link fit}. */
  private offset: [number, number] = [0, 0];
  private readonly labels = new CSS2DRenderer();
  private labelObjects: CSS2DObject[] = [];
  /** Level 0's graphics (the control mesh) and the shown level's, for picking. */
  private control: LevelGraphics | null = null;
  private shown: LevelGraphics | null = null;
  private readonly materials = new SurfaceMaterials();
  /** The shown level is the control mesh: drawn with face normals (a cube looks like a cube). */
  private controlShown = false;
  private bboxHelper: Box3Helper | null = null;
  private readonly overlays = new Map<OverlayName, boolean>(
    Object.entries(OVERLAY_DEFAULTS) as [OverlayName, boolean][],
  );
  private mode: RenderMode = 'smooth';
  private radius = 1;
  /** A tool's own objects (setExtras). */
  private extras: Object3D | null = null;
  private dirty = true;
  private frame = 0;
  private readonly resizeObserver: ResizeObserver;
  private readonly visibilityObserver: IntersectionObserver;
  /** Off screen (e.g. one of several embeds scrolled away): nothing is drawn. */
  private onScreen = true;
  /** Called after the camera moved (pointer, keys, fit or setView). */
  onViewChange: (() => void) | null = null;
  /** Called when a picture of the view is in its canvas (after each {@link render}). */
  onDraw: (() => void) | null = null;
  /** Called on a click (press and release without dragging the camera) of the primary button. */
  onClick: ((click: ViewClick) => void) | null = null;

  constructor(private readonly container: HTMLElement) {
    this.renderer = sharedRenderer();
    this.detach = this.renderer.attach(() => this.requestRender());
    this.canvas = document.createElement('canvas');
    this.canvas.classList.add('subdiv-canvas');
    // Inline, so the view fills its container inside any page or shadow root.
    this.canvas.style.cssText = 'display:block;width:100%;height:100%;touch-action:none';
    const context = this.canvas.getContext('2d');
    if (!context) throw new Error('This browser cannot draw on a canvas.');
    this.context = context;
    container.append(this.canvas);
    this.mapping = new ClientMapping(container);

    this.camera = new PerspectiveCamera(35, 1, 0.01, 100);
    this.scene.add(this.camera);
    addLights(this.scene, this.camera);
    this.surface = new Mesh(undefined, this.materials.smooth);
    // Sharp edges and corners (their colours say how sharp): drawn over everything else.
    this.creaseLines = new LineSegments2(
      new LineSegmentsGeometry(),
      new LineMaterial({ vertexColors: true, linewidth: 4 }),
    );
    this.creaseLines.renderOrder = 3;
    this.borderLines = new LineSegments2(
      new LineSegmentsGeometry(),
      new LineMaterial({ color: VIEW_COLORS.border, linewidth: 3 }),
    );
    this.borderLines.renderOrder = 0.5;
    this.cornerPoints = new Points(
      new BufferGeometry(),
      new PointsMaterial({ vertexColors: true, size: 12, sizeAttenuation: false }),
    );
    this.cornerPoints.renderOrder = 4;
    // The selection: three times as wide as a crease (half of a line on an edge is behind the
    // surface), so that a sharp edge shows its colour inside the selection.
    this.selectedLines = new LineSegments2(
      new LineSegmentsGeometry(),
      // Pushed back half as far as the surface (polygonOffset 1), so that a crease drawn on
      // the same edge stays in front of it and it in front of the surface.
      new LineMaterial({
        color: VIEW_COLORS.selection,
        linewidth: 12,
        polygonOffset: true,
        polygonOffsetFactor: 0.5,
        polygonOffsetUnits: 0.5,
      }),
    );
    this.selectedLines.renderOrder = 2.5;
    this.selectedPoints = new Points(
      new BufferGeometry(),
      new PointsMaterial({ color: VIEW_COLORS.selection, size: 18, sizeAttenuation: false }),
    );
    this.selectedPoints.renderOrder = 3.5;
    this.parentPoints = new Points(
      new BufferGeometry(),
      new PointsMaterial({ color: VIEW_COLORS.parents, size: 12, sizeAttenuation: false }),
    );
    this.parentPoints.renderOrder = 3.5;
    this.parentLines = new LineSegments2(
      new LineSegmentsGeometry(),
      new LineMaterial({ color: VIEW_COLORS.parents, transparent: true, opacity: 0.7 }),
    );
    this.parentLines.renderOrder = 3;
    this.labels.domElement.style.cssText = 'position:absolute;inset:0;pointer-events:none;overflow:hidden';
    container.append(this.labels.domElement);
    for (const object of [
      this.surface,
      this.lines.edges,
      this.lines.control,
      this.lines.curves,
      this.lines.thinEdges,
      this.lines.thinControl,
      this.lines.thinCurves,
      this.creaseLines,
      this.borderLines,
      this.cornerPoints,
      this.selectedLines,
      this.selectedPoints,
      this.parentPoints,
      this.parentLines,
    ]) {
      object.visible = false;
      object.frustumCulled = false;
      this.scene.add(object);
    }

    this.controls = new MappedTrackballControls(this.camera, this.canvas, this.mapping);
    this.controls.rotateSpeed = 3;
    this.controls.zoomSpeed = 1.2;
    this.controls.panSpeed = 0.8;
    // No inertia: a view stops where the user leaves it, so saved views restore exactly
    // and nothing keeps redrawing afterwards.
    this.controls.staticMoving = true;
    // The app uses S for Subdivide; trackball's hold-a-key drag modes would steal A/S/D.
    this.controls.keys = ['', '', ''];
    this.controls.addEventListener('change', () => {
      this.updateClipping();
      this.dirty = true;
      this.onViewChange?.();
    });

    let press: { x: number; y: number } | null = null;
    this.canvas.addEventListener('pointerdown', (event) => {
      press = event.button === 0 ? { x: event.clientX, y: event.clientY } : null;
    });
    this.canvas.addEventListener('pointerup', (event) => {
      if (!press || event.button !== 0) return;
      const moved = Math.hypot(event.clientX - press.x, event.clientY - press.y);
      press = null;
      if (moved > CLICK_SLOP || !this.onClick) return;
      const at = this.mapping.toLocal({ x: event.clientX, y: event.clientY });
      this.onClick({
        x: at.x,
        y: at.y,
        altKey: event.altKey,
        shiftKey: event.shiftKey,
      });
    });

    this.resizeObserver = new ResizeObserver(() => this.resize());
    this.resizeObserver.observe(container);
    this.visibilityObserver = new IntersectionObserver((entries) => {
      this.onScreen = entries.some((entry) => entry.isIntersecting);
      if (this.onScreen) this.dirty = true;
    });
    this.visibilityObserver.observe(container);
    this.resize();
    this.fitSphere(new Sphere(new Vector3(), 1));
    const loop = () => {
      this.frame = requestAnimationFrame(loop);
      if (!this.onScreen) return;
      this.controls.update();
      // A large new level goes to the GPU a few megabytes a frame before its first draw.
      if (this.dirty && !this.renderer.upload(this.shownGeometries())) this.render();
    };
    this.frame = requestAnimationFrame(loop);
  }

  /**
   * Shows a level (null: nothing); `control`: it is the control mesh, drawn
   * with face normals whatever the mode. The caller keeps ownership of `graphics`.
   */
  setLevel(graphics: LevelGraphics | null, control = false): void {
    this.shown = graphics;
    this.controlShown = control;
    if (graphics) {
      showParts(this.surface, graphics.surfaceParts);
      this.materials.setSide(graphics.side);
      if (graphics.creases) this.creaseLines.geometry = graphics.creases;
      if (graphics.corners) this.cornerPoints.geometry = graphics.corners;
      if (graphics.borders) this.borderLines.geometry = graphics.borders;
    }
    this.applyMaterial();
    this.surface.userData.hasLevel = graphics !== null;
    this.lines.curves.userData.hasLevel = graphics?.curves != null;
    this.creaseLines.userData.hasLevel = graphics?.creases != null;
    this.cornerPoints.userData.hasLevel = graphics?.corners != null;
    this.borderLines.userData.hasLevel = graphics?.borders != null;
    this.applyVisibility();
  }

  /** The level-0 graphics whose polygon edges form the control-mesh overlay. */
  setControlMesh(graphics: LevelGraphics | null): void {
    this.control = graphics;
    this.lines.control.userData.hasLevel = graphics !== null;
    this.applyVisibility();
  }

  /** The box drawn by the bounding-box overlay (from the core's facts). */
  setBoundingBox(min: readonly number[] | null, max: readonly number[] | null): void {
    if (this.bboxHelper) {
      this.scene.remove(this.bboxHelper);
      this.bboxHelper.dispose();
      this.bboxHelper = null;
    }
    if (min && max) {
      const box = new Box3(new Vector3(min[0], min[1], min[2]), new Vector3(max[0], max[1], max[2]));
      this.bboxHelper = new Box3Helper(box, new Color(VIEW_COLORS.bbox));
      this.scene.add(this.bboxHelper);
    }
    this.applyVisibility();
  }

  get renderMode(): RenderMode {
    return this.mode;
  }

  setRenderMode(mode: RenderMode): void {
    this.mode = mode;
    this.applyMaterial();
    this.applyVisibility();
  }

  /**
   * The surface's material for the mode and level: face normals in flat mode
   * and for the control mesh (its polygons are the shape), vertex normals
   * otherwise (edges go over smooth shading: flat shading of a non-planar quad
   * would show its fan diagonal); reflection lines in zebra mode.
   */
  private applyMaterial(): void {
    const flat = this.mode === 'flat' || this.controlShown;
    this.surface.material = this.materials.forMode(this.mode === 'zebra', flat);
    for (const part of this.surface.children) (part as Mesh).material = this.surface.material;
  }

  overlay(name: OverlayName): boolean {
    return this.overlays.get(name) ?? false;
  }

  setOverlay(name: OverlayName, visible: boolean): void {
    this.overlays.set(name, visible);
    this.applyVisibility();
  }

  /** Points the camera at `sphere` from the default direction, at a distance that shows all of it. */
  fitSphere(sphere: Sphere): void {
    this.radius = Math.max(sphere.radius, 1e-9);
    const distance = fitDistance(this.radius, this.camera.fov, this.camera.aspect);
    this.controls.target.copy(sphere.center);
    this.camera.up.set(0, 1, 0);
    this.camera.position.copy(sphere.center).addScaledVector(DEFAULT_VIEW_DIRECTION, distance);
    this.camera.lookAt(sphere.center);
    this.updateClipping();
    this.controls.update();
    this.dirty = true;
    this.onViewChange?.();
  }

  /**
   * Frames what is shown (fit.ts): the level, the cage when it is drawn and
   * a tool's objects, inside the part of the view no panel marked
   * `data-covers-view` covers; looking from `view` (a canonical view's
   * direction and up) or from the default direction. `also`: more points
   * (xyz) to keep in the picture (other panes' levels).
   */
  fit(view?: { direction: readonly number[]; up: readonly number[] }, also: readonly ArrayLike<number>[] = []): void {
    const points: ArrayLike<number>[] = [...also];
    if (this.shown) points.push(this.shown.points);
    if (this.control && this.control !== this.shown && this.lines.control.visible) points.push(this.control.points);
    if (this.extras) {
      const box = new Box3().setFromObject(this.extras);
      // As the level's, a Float32Array: one kind of array keeps fitCamera's loops fast.
      if (!box.isEmpty()) points.push(new Float32Array([...box.min.toArray(), ...box.max.toArray()]));
    }
    this.fitTo(points, view, false);
  }

  /**
   * Frames `points` (xyz each) alone, as {@link fit} frames what is shown: a
   * tool's part of the model (Inspect's crossing faces). The clipping planes
   * still reach the whole model.
   */
  fitPoints(
    points: readonly ArrayLike<number>[],
    view?: { direction: readonly number[]; up: readonly number[] },
  ): void {
    this.fitTo(points, view, true);
  }

  private fitTo(
    points: readonly ArrayLike<number>[],
    view: { direction: readonly number[]; up: readonly number[] } | undefined,
    part: boolean,
  ): void {
    const direction = view ? new Vector3().fromArray(view.direction) : DEFAULT_VIEW_DIRECTION.clone();
    const up = new Vector3().fromArray(view?.up ?? [0, 1, 0]);
    const { width, height } = this.size;
    // The view may have changed size since the resize observer last ran (a pane was just added beside it).
    if (Math.abs(this.camera.aspect - width / height) > 1e-9) this.resize();
    const covers = [...this.container.querySelectorAll<HTMLElement>('[data-covers-view]')]
      .filter((e) => e.getClientRects().length > 0)
      .map((e) => this.mapping.boxOf(e));
    const fitted = fitCamera({
      points,
      direction,
      up,
      fov: this.camera.fov,
      aspect: this.camera.aspect,
      free: freeRect(width, height, covers),
    });
    if (!fitted) return;
    this.offset = fitted.offset;
    this.applyOffset();
    this.radius = Math.max(fitted.radius, part ? this.radius : 1e-9);
    this.setView({
      position: fitted.position.toArray(),
      target: fitted.target.toArray(),
      up: fitted.up.toArray(),
    });
  }

  /** The direction from the target to the camera, and the camera's up: where it looks from now. */
  lookDirection(): { direction: number[]; up: number[] } {
    const direction = this.camera.position.clone().sub(this.controls.target);
    return { direction: direction.toArray(), up: this.camera.up.toArray() };
  }

  /** Where the target is drawn, in NDC (x right, y up): Fit's shift that keeps the model clear of the panels. */
  get viewOffset(): [number, number] {
    return [...this.offset];
  }

  /**
   * The camera a picture of the view is drawn with (PNG, SVG, PDF, EPS):
   * this one without Fit's shift, since the panels it clears are not in the
   * picture; a fitted model is then in the picture's middle, as large as on
   * screen. A copy, without the lights that ride with the view's camera.
   */
  pictureCamera(): PerspectiveCamera {
    const camera = new PerspectiveCamera().copy(this.camera, false);
    camera.clearViewOffset();
    camera.updateMatrixWorld();
    return camera;
  }

  /** Shifts the projection by {@link offset} (three's view offset; none when it is zero). */
  private applyOffset(): void {
    const { width, height } = this.size;
    if (this.offset[0] === 0 && this.offset[1] === 0) {
      this.camera.clearViewOffset();
      return;
    }
    const [x, y] = viewOffsetPixels(this.offset, width, height);
    this.camera.setViewOffset(width, height, x, y, width, height);
  }

  /** Sets the line-width setting (CSS pixels; line-style.ts). */
  setLineWidth(width: number): void {
    this.lines.width = width;
    this.dirty = true;
  }

  get lineWidthSetting(): number {
    return this.lines.width;
  }

  /** The opacity the polygon edges (of `level`: the shown one, or the cage) are drawn with now (line-style.ts, edgeOpacity). */
  edgeOpacity(level: LevelGraphics | null = this.shown): number {
    const distance = this.camera.position.distanceTo(this.controls.target);
    return level ? this.lines.edgeOpacity(level, this.camera, distance, this.size.height) : 1;
  }

  /** The opacity the control mesh is drawn with now: its own edges' (1 without a control mesh). */
  cageOpacity(): number {
    return this.edgeOpacity(this.control);
  }

  /** Gives each fat line its width for a picture of `pixelsPerCss` device pixels a CSS pixel, and the edges and the cage their opacity. */
  private styleLines(pixelsPerCss: number): void {
    const opacity = { edges: this.edgeOpacity(), control: this.cageOpacity() };
    this.lines.style(pixelsPerCss, this.shown, this.control, opacity, [
      [this.creaseLines, 'creases'],
      [this.parentLines, 'parents'],
      [this.borderLines, 'border'],
    ]);
    // The selection is a marker of fixed size, only scaled with the picture.
    this.selectedLines.material.linewidth = 12 * pixelsPerCss;
    // A tool's fat lines that name their width in CSS pixels (the halfedge arrows) scale the same way.
    this.extras?.traverse((object) => {
      const css = object.userData.cssLineWidth;
      if (object instanceof LineSegments2 && typeof css === 'number') object.material.linewidth = css * pixelsPerCss;
    });
  }

  /** The current viewpoint. */
  getView(): ViewState {
    const p = this.camera.position;
    const t = this.controls.target;
    const u = this.camera.up;
    return { position: [p.x, p.y, p.z], target: [t.x, t.y, t.z], up: [u.x, u.y, u.z] };
  }

  setView(view: ViewState): void {
    this.camera.position.fromArray(view.position);
    this.camera.up.fromArray(view.up).normalize();
    this.controls.target.fromArray(view.target);
    this.camera.lookAt(this.controls.target);
    this.updateClipping();
    this.controls.update();
    this.dirty = true;
    this.onViewChange?.();
  }

  /** Keyboard camera moves (camera-moves.ts): turns about the target, around the camera's up and right axes. */
  orbit(yawDeg: number, pitchDeg: number): void {
    orbitCamera(this.camera, this.controls.target, yawDeg, pitchDeg);
    this.afterKeyboardMove();
  }

  /** Moves the camera towards the target (factor < 1) or away from it (factor > 1). */
  zoom(factor: number): void {
    zoomCamera(this.camera, this.controls.target, factor);
    this.afterKeyboardMove();
  }

  /** Slides camera and target sideways by fractions of the view's height. */
  pan(dx: number, dy: number): void {
    panCamera(this.camera, this.controls.target, dx, dy);
    this.afterKeyboardMove();
  }

  private afterKeyboardMove(): void {
    this.camera.lookAt(this.controls.target);
    this.updateClipping();
    this.controls.update();
    this.dirty = true;
    this.onViewChange?.();
  }

  /** The control vertex or edge drawn under (x, y), CSS pixels from the view's top left (see pick.ts). */
  pickControl(x: number, y: number): Pick | null {
    if (!this.control) return null;
    const { width, height } = this.size;
    return pickElement(this.control, this.camera, x, y, width, height, true);
  }

  /** The vertex of the shown level drawn under (x, y), or null. */
  pickVertex(x: number, y: number): number | null {
    if (!this.shown) return null;
    const { width, height } = this.size;
    const pick = pickElement(this.shown, this.camera, x, y, width, height, false);
    return pick?.kind === 'vertex' ? pick.vertex : null;
  }

  /** Where vertex `v` of the control mesh (or, with `shown`, of the shown level) is drawn, CSS pixels from the view's top left (null: not in view). */
  vertexOnScreen(v: number, shown = false): { x: number; y: number } | null {
    const level = shown ? this.shown : this.control;
    if (!level) return null;
    const { width, height } = this.size;
    return screenPointOf(level, this.camera, v, width, height);
  }

  /** Where the view's point (x, y) (its own CSS pixels from its top left) is in the page's viewport (client coordinates). */
  toClient(x: number, y: number): { x: number; y: number } {
    return this.mapping.toClient({ x, y });
  }

  /**
   * Marks control edges (`segments`: x y z of both ends, six numbers an
   * edge) and vertices (`points`: three numbers each) as selected; empty
   * arrays clear the marks.
   */
  setSelection(segments: Float32Array, points: Float32Array): void {
    this.selectedLines.geometry.dispose();
    this.selectedLines.geometry = new LineSegmentsGeometry().setPositions(segments);
    this.selectedLines.visible = segments.length > 0;
    this.selectedPoints.geometry.dispose();
    this.selectedPoints.geometry = new BufferGeometry();
    this.selectedPoints.geometry.setAttribute('position', new Float32BufferAttribute(points, 3));
    this.selectedPoints.visible = points.length > 0;
    this.dirty = true;
  }

  /**
   * Marks parent vertices (`parents`: x y z each) with points and labels
   * (`labels[i]` at parent i, e.g. its weight "3/8"), each joined by a thin
   * line to `vertex`, the point they make (marked with
   * {@link setSelection}); empty arrays clear them.
   */
  setParents(parents: Float32Array, labels: readonly string[], vertex: readonly number[] = []): void {
    this.parentPoints.geometry.dispose();
    this.parentPoints.geometry = new BufferGeometry();
    this.parentPoints.geometry.setAttribute('position', new Float32BufferAttribute(parents, 3));
    this.parentPoints.visible = parents.length > 0;
    const spokes = new Float32Array(2 * parents.length);
    if (vertex.length === 3) {
      for (let i = 0; i < parents.length / 3; ++i) {
        spokes.set(vertex, 6 * i);
        spokes.set(parents.subarray(3 * i, 3 * i + 3), 6 * i + 3);
      }
    }
    this.parentLines.geometry.dispose();
    this.parentLines.geometry = new LineSegmentsGeometry().setPositions(spokes);
    this.parentLines.visible = vertex.length === 3 && parents.length > 0;
    for (const object of this.labelObjects) {
      this.scene.remove(object);
      object.element.remove();
    }
    this.labelObjects = labels.map((text, i) => {
      const element = document.createElement('span');
      element.textContent = text;
      element.dataset.testid = 'view.stencil-label';
      // The panel lists the same weights; a screen reader need not hear the picture's copies.
      element.setAttribute('aria-hidden', 'true');
      element.style.cssText =
        'font:12px/1.3 system-ui,sans-serif;padding:0 4px;border-radius:3px;' +
        `background:rgba(255,255,255,0.88);color:#1f2937;border:1px solid ${VIEW_COLORS.parents}`;
      const object = new CSS2DObject(element);
      object.position.fromArray(parents, 3 * i);
      // Above its point, so that the point stays visible.
      object.center.set(0.5, 1.35);
      this.scene.add(object);
      return object;
    });
    this.dirty = true;
  }

  /**
   * Draws a tool's own objects with the level (Inspect's faces, sphere, hull
   * and planes), in place of the last ones; null: none. The caller keeps
   * and disposes them.
   */
  setExtras(object: Object3D | null): void {
    if (this.extras) this.scene.remove(this.extras);
    this.extras = object;
    if (object) this.scene.add(object);
    this.dirty = true;
  }

  /** Moves the camera to show `sphere`, looking from where it looks now. */
  frameSphere(sphere: Sphere): void {
    const direction = this.camera.position.clone().sub(this.controls.target).normalize();
    const distance = fitDistance(Math.max(sphere.radius, 1e-9), this.camera.fov, this.camera.aspect);
    this.controls.target.copy(sphere.center);
    this.camera.position.copy(sphere.center).addScaledVector(direction, distance);
    this.camera.lookAt(sphere.center);
    this.updateClipping();
    this.controls.update();
    this.dirty = true;
    this.onViewChange?.();
  }

  /**
   * Draws the surface in its vertices' colours (LevelGraphics.setColors) or
   * in its one colour.
   */
  setVertexColors(on: boolean): void {
    this.materials.setVertexColors(on);
    this.dirty = true;
  }

  /** Whether the last draw showed the polygon edges as WebGL's one-pixel lines (a dense level: view-lines.ts). */
  thinEdges(): boolean {
    return this.lines.thinEdges.visible;
  }

  /** Line segments the edge overlay draws for the shown level (polygon edges, no fan diagonals). */
  edgeSegments(): number {
    return (this.shown?.edges.index?.count ?? 0) / 2;
  }

  /** Geometries and textures alive on the GPU for the whole page (three's renderer.info), for leak checks. */
  gpuMemory(): { geometries: number; textures: number } {
    return this.renderer.memory();
  }

  /**
   * The colour behind the model (a CSS colour; null: transparent, over a
   * page that is dark when `darkBehind`).
   */
  setBackground(color: string | null, darkBehind = false): void {
    this.background = color;
    // Polygon edges stay visible on a dark background.
    const dark = color === null ? darkBehind : new Color(color).getHSL({ h: 0, s: 0, l: 0 }).l < 0.35;
    this.lines.setEdgeColor(dark ? VIEW_COLORS.edgesOnDark : VIEW_COLORS.edges);
    this.dirty = true;
  }

  /** Marks the picture out of date; it is redrawn on the next animation frame. */
  requestRender(): void {
    this.dirty = true;
  }

  /** Draws now. */
  render(): void {
    this.dirty = false;
    this.styleLines(this.canvas.width / this.size.width);
    this.renderer.draw(this.scene, this.camera, this.context, this.canvas.width, this.canvas.height, this.background);
    if (this.labelObjects.length > 0) this.labels.render(this.scene, this.camera);
    this.onDraw?.();
  }

  /** The geometries the next draw needs on the GPU. */
  private shownGeometries(): BufferGeometry[] {
    const parts = [this.surface, ...this.surface.children.filter((c) => c.visible)] as Mesh[];
    const surface = this.surface.visible ? parts.map((o) => o.geometry) : [];
    return [...surface, ...this.lines.geometries(this.shown, this.control)];
  }

  /** Size of the view in CSS pixels. */
  get size(): { width: number; height: number } {
    return this.mapping.size;
  }

  /**
   * PNG of the view at `scale` × its CSS size, optionally with a transparent
   * background: drawn once into a canvas of that size, by {@link pictureCamera}.
   */
  exportPng(scale: number, transparent: boolean): Promise<Blob> {
    const { width, height } = this.size;
    const w = Math.round(width * scale);
    const h = Math.round(height * scale);
    const maxSize = this.renderer.maxSize;
    if (w > maxSize || h > maxSize) {
      return Promise.reject(
        new Error(`A ×${scale} image would be ${w}×${h} pixels; this GPU draws at most ${maxSize}×${maxSize}.`),
      );
    }
    const canvas = document.createElement('canvas');
    canvas.width = w;
    canvas.height = h;
    const context = canvas.getContext('2d');
    if (!context) return Promise.reject(new Error('This browser cannot draw on a canvas.'));
    // Lines as wide, relative to the picture, as on screen: ×4 pixels, ×4 line widths.
    this.styleLines(w / width);
    this.renderer.draw(this.scene, this.pictureCamera(), context, w, h, transparent ? null : this.background);
    this.styleLines(this.canvas.width / width);
    if (w > this.canvas.width || h > this.canvas.height) this.renderer.shrink();
    return new Promise<Blob>((resolve, reject) =>
      canvas.toBlob((b) => (b ? resolve(b) : reject(new Error('The browser could not encode the PNG.'))), 'image/png'),
    );
  }

  /** Stops drawing and frees the renderer, materials and helpers (not the caller's LevelGraphics). */
  dispose(): void {
    cancelAnimationFrame(this.frame);
    this.detach();
    this.resizeObserver.disconnect();
    this.visibilityObserver.disconnect();
    this.controls.dispose();
    this.mapping.dispose();
    this.setBoundingBox(null, null);
    this.materials.dispose();
    this.lines.dispose();
    this.creaseLines.material.dispose();
    this.borderLines.material.dispose();
    (this.cornerPoints.material as PointsMaterial).dispose();
    this.setParents(new Float32Array(0), []);
    this.labels.domElement.remove();
    for (const object of [this.selectedLines, this.selectedPoints, this.parentPoints]) {
      object.geometry.dispose();
      object.material.dispose();
    }
    this.parentLines.geometry.dispose();
    this.parentLines.material.dispose();
    this.canvas.remove();
  }

  private applyVisibility(): void {
    const hasLevel = this.surface.userData.hasLevel === true;
    this.surface.visible = hasLevel && this.mode !== 'wireframe';
    this.lines.edges.visible = hasLevel && (this.mode === 'edges' || this.mode === 'wireframe');
    this.lines.control.visible = this.lines.control.userData.hasLevel === true && this.overlay('control');
    this.lines.curves.visible = this.lines.curves.userData.hasLevel === true && this.overlay('curves');
    this.borderLines.visible = this.lines.edges.visible && this.borderLines.userData.hasLevel === true;
    this.creaseLines.visible = this.creaseLines.userData.hasLevel === true && this.overlay('creases');
    this.cornerPoints.visible = this.cornerPoints.userData.hasLevel === true && this.overlay('creases');
    if (this.bboxHelper) this.bboxHelper.visible = this.overlay('bbox');
    this.dirty = true;
  }

  private resize(): void {
    const { width, height } = this.size;
    const ratio = window.devicePixelRatio || 1;
    this.canvas.width = Math.round(width * ratio);
    this.canvas.height = Math.round(height * ratio);
    this.camera.aspect = width / height;
    this.applyOffset();
    this.camera.updateProjectionMatrix();
    this.labels.setSize(width, height);
    this.controls.handleResize();
    // Off screen (maybe with its GPU copies given back) it draws when it comes back.
    if (this.onScreen) this.render();
    else this.dirty = true;
  }

  /** Near and far planes that follow the camera distance, so zooming never clips the model. */
  private updateClipping(): void {
    const distance = this.camera.position.distanceTo(this.controls.target);
    this.camera.near = Math.max(distance * 0.005, this.radius * 1e-4);
    this.camera.far = 2 * distance + 4 * this.radius;
    this.camera.updateProjectionMatrix();
  }
}
