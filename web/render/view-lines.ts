/**
 * A view's lines of the level: the polygon edges, the control mesh (cage)
 * and the marked control-edge curves, as three.js fat lines, with the
 * line-width setting and the edges' fading (line-style.ts). SceneView adds
 * the objects to its scene and decides when the three line kinds are
 * visible; polygon edges, a cage or curves of more than DENSE_LINE_SEGMENTS
 * segments are drawn by their thin counterparts instead (level-graphics.ts).
 */
import { type BufferGeometry, LineBasicMaterial, LineSegments, type PerspectiveCamera } from 'three';
import { LineMaterial } from 'three/addons/lines/LineMaterial.js';
import { LineSegments2 } from 'three/addons/lines/LineSegments2.js';
import { LineSegmentsGeometry } from 'three/addons/lines/LineSegmentsGeometry.js';
import { denseLines, type LevelGraphics, NO_GEOMETRY, showParts } from './level-graphics';
import {
  DEFAULT_LINE_WIDTH,
  edgeOpacity,
  fatLinesOf,
  type LineKind,
  lineWidthPx,
  meanSegmentLength,
  projectedLength,
} from './line-style';

/** What a fat line draws while its thin counterpart draws a dense level: nothing. */
const EMPTY_FAT = new LineSegmentsGeometry();

export class ViewLines {
  readonly edges: LineSegments2;
  readonly control: LineSegments2;
  readonly curves: LineSegments2;
  /**
   * The polygon edges and the cage of a dense level, one device pixel wide
   * over the level's own index parts: visible, in place of the fat ones
   * (then given no segments), when those are visible and dense.
   */
  readonly thinEdges: LineSegments<BufferGeometry, LineBasicMaterial>;
  readonly thinControl: LineSegments<BufferGeometry, LineBasicMaterial>;
  /** The control-edge curves of a dense level, likewise. */
  readonly thinCurves: LineSegments<BufferGeometry, LineBasicMaterial>;
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
    // Transparent as well: a cage of a scanned mesh crowds as a fine level does.
    this.control = new LineSegments2(
      new LineSegmentsGeometry(),
      new LineMaterial({ color: colors.control, transparent: true }),
    );
    this.control.renderOrder = 1;
    this.curves = new LineSegments2(new LineSegmentsGeometry(), new LineMaterial({ color: colors.curves }));
    this.curves.renderOrder = 2;
    this.thinEdges = new LineSegments(NO_GEOMETRY, new LineBasicMaterial({ color: colors.edges, transparent: true }));
    this.thinControl = new LineSegments(
      NO_GEOMETRY,
      new LineBasicMaterial({ color: colors.control, transparent: true }),
    );
    this.thinControl.renderOrder = 1;
    this.thinCurves = new LineSegments(NO_GEOMETRY, new LineBasicMaterial({ color: colors.curves }));
    this.thinCurves.renderOrder = 2;
  }

  /** The polygon edges' colour (darker or lighter with the background). */
  setEdgeColor(color: string): void {
    this.edges.material.color.set(color);
    this.thinEdges.material.color.set(color);
  }

  /**
   * The opacity of `level`'s polygon edges (those of the shown level, or the
   * cage's) seen by `camera` at `distance` from its target in a view
   * `heightPx` CSS pixels tall: by their mean length on screen at the
   * target's depth (line-style.ts, edgeOpacity).
   */
  edgeOpacity(level: LevelGraphics, camera: PerspectiveCamera, distance: number, heightPx: number): number {
    let mean = this.meanEdge.get(level);
    if (mean === undefined) {
      mean = meanSegmentLength(level.points, level.edges.index?.array ?? []);
      this.meanEdge.set(level, mean);
    }
    return edgeOpacity(projectedLength(mean, distance, camera, heightPx), this.width);
  }

  /**
   * Gives these lines and `others` their widths for a picture of
   * `pixelsPerCss` device pixels a CSS pixel, the edges and the cage their
   * `opacity`, and the visible ones the fat lines of `shown` and `control`
   * (made when first drawn, refilled when Split moves the points) or, dense,
   * their thin lines.
   */
  style(
    pixelsPerCss: number,
    shown: LevelGraphics | null,
    control: LevelGraphics | null,
    opacity: { edges: number; control: number },
    others: readonly [LineSegments2, LineKind][],
  ): void {
    const widths: [LineSegments2, LineKind][] = [
      [this.edges, 'edges'],
      [this.control, 'control'],
      [this.curves, 'curves'],
      ...others,
    ];
    for (const [line, kind] of widths) line.material.linewidth = lineWidthPx(kind, this.width, pixelsPerCss);
    this.edges.material.opacity = opacity.edges;
    this.thinEdges.material.opacity = opacity.edges;
    this.control.material.opacity = opacity.control;
    this.thinControl.material.opacity = opacity.control;
    for (const { fat, thin, lines, parts } of this.kinds(shown, control)) {
      const dense = fat.visible && lines !== null && denseLines(lines);
      thin.visible = dense;
      // Not dense: the thin lines let go of the level they drew.
      showParts(thin, dense ? parts : [NO_GEOMETRY]);
      if (dense) fat.geometry = EMPTY_FAT;
      else if (fat.visible && lines) fat.geometry = fatLinesOf(lines);
    }
  }

  /** The line geometries the next draw needs (of the visible lines): fat lines, or a dense level's index parts. */
  geometries(shown: LevelGraphics | null, control: LevelGraphics | null): BufferGeometry[] {
    return this.kinds(shown, control).flatMap(({ fat, lines, parts }) =>
      !fat.visible || !lines ? [] : denseLines(lines) ? parts : [fatLinesOf(lines)],
    );
  }

  /**
   * Each kind of line with what it draws: the shown level's polygon edges,
   * the cage's, and the shown level's marked control edges (their index
   * whole: a level marks at most as many edges as it has).
   */
  private kinds(shown: LevelGraphics | null, control: LevelGraphics | null) {
    return [
      { fat: this.edges, thin: this.thinEdges, lines: shown?.edges ?? null, parts: shown?.edgeParts ?? [] },
      { fat: this.control, thin: this.thinControl, lines: control?.edges ?? null, parts: control?.edgeParts ?? [] },
      {
        fat: this.curves,
        thin: this.thinCurves,
        lines: shown?.curves ?? null,
        parts: shown?.curves ? [shown.curves] : [],
      },
    ];
  }

  /** Frees the materials (the fat geometries go with their levels). */
  dispose(): void {
    this.edges.material.dispose();
    this.control.material.dispose();
    this.curves.material.dispose();
    this.thinEdges.material.dispose();
    this.thinControl.material.dispose();
    this.thinCurves.material.dispose();
  }
}
