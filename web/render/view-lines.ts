/**
 * A view's lines of the level: the polygon edges, the control mesh (cage)
 * and the marked control-edge curves, as three.js fat lines, with the
 * line-width setting and the edges' fading (line-style.ts). SceneView adds
 * the three objects to its scene and decides when each is visible.
 */
import type { BufferGeometry, PerspectiveCamera } from 'three';
import { LineMaterial } from 'three/addons/lines/LineMaterial.js';
import { LineSegments2 } from 'three/addons/lines/LineSegments2.js';
import { LineSegmentsGeometry } from 'three/addons/lines/LineSegmentsGeometry.js';
import type { LevelGraphics } from './level-graphics';
import {
  DEFAULT_LINE_WIDTH,
  edgeOpacity,
  fatLinesOf,
  type LineKind,
  lineWidthPx,
  meanSegmentLength,
  projectedLength,
} from './line-style';

export class ViewLines {
  readonly edges: LineSegments2;
  readonly control: LineSegments2;
  readonly curves: LineSegments2;
  /** The line-width setting, CSS pixels. */
  width = DEFAULT_LINE_WIDTH;
  /** Mean 3D length of each level's polygon edges, for the edges' fading. */
  private readonly meanEdge = new WeakMap<LevelGraphics, number>();

  constructor(colors: { edges: string; control: string; curves: string }) {
    // Transparent: the edges fade as they crowd.
    this.edges = new LineSegments2(
      new LineSegmentsGeometry(),
      new LineMaterial({ color: colors.edges, transparent: true }),
    );
    this.control = new LineSegments2(new LineSegmentsGeometry(), new LineMaterial({ color: colors.control }));
    this.control.renderOrder = 1;
    this.curves = new LineSegments2(new LineSegmentsGeometry(), new LineMaterial({ color: colors.curves }));
    this.curves.renderOrder = 2;
  }

  /**
   * The opacity of `shown`'s polygon edges seen by `camera` at `distance`
   * from its target in a view `heightPx` CSS pixels tall: by their mean
   * length on screen at the target's depth (line-style.ts, edgeOpacity).
   */
  edgeOpacity(shown: LevelGraphics, camera: PerspectiveCamera, distance: number, heightPx: number): number {
    let mean = this.meanEdge.get(shown);
    if (mean === undefined) {
      mean = meanSegmentLength(shown.surface.getAttribute('position').array, shown.edges.index?.array ?? []);
      this.meanEdge.set(shown, mean);
    }
    return edgeOpacity(projectedLength(mean, distance, camera, heightPx), this.width);
  }

  /**
   * Gives these lines and `others` their widths for a picture of
   * `pixelsPerCss` device pixels a CSS pixel, the edges `opacity`, and the
   * visible ones the fat lines of `shown` and `control` (made when first
   * drawn, refilled when Split moves the points).
   */
  style(
    pixelsPerCss: number,
    shown: LevelGraphics | null,
    control: LevelGraphics | null,
    opacity: number,
    others: readonly [LineSegments2, LineKind][],
  ): void {
    const widths: [LineSegments2, LineKind][] = [
      [this.edges, 'edges'],
      [this.control, 'control'],
      [this.curves, 'curves'],
      ...others,
    ];
    for (const [line, kind] of widths) line.material.linewidth = lineWidthPx(kind, this.width, pixelsPerCss);
    this.edges.material.opacity = opacity;
    if (this.edges.visible && shown) this.edges.geometry = fatLinesOf(shown.edges);
    if (this.control.visible && control) this.control.geometry = fatLinesOf(control.edges);
    if (this.curves.visible && shown?.curves) this.curves.geometry = fatLinesOf(shown.curves);
  }

  /** The fat-line geometries the next draw needs (of the visible lines). */
  geometries(shown: LevelGraphics | null, control: LevelGraphics | null): BufferGeometry[] {
    const lines = [
      this.edges.visible && shown ? fatLinesOf(shown.edges) : null,
      this.control.visible && control ? fatLinesOf(control.edges) : null,
      this.curves.visible && shown?.curves ? fatLinesOf(shown.curves) : null,
    ];
    return lines.filter((g) => g !== null);
  }

  /** Frees the materials (the fat geometries go with their levels). */
  dispose(): void {
    this.edges.material.dispose();
    this.control.material.dispose();
    this.curves.material.dispose();
  }
}
