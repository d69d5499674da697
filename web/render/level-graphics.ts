/**
 * GPU geometry of one level, built from the core's render buffers: a
 * triangle geometry for the surface and a line geometry of the *polygon*
 * edges (so quads are drawn as quads, never as triangle pairs). Both share
 * one position attribute. Call dispose() when the level is dropped.
 */
import {
  BackSide,
  BufferAttribute,
  BufferGeometry,
  Color,
  DoubleSide,
  Float32BufferAttribute,
  FrontSide,
  LineSegments,
  Mesh,
  type Side,
  Sphere,
  Vector3,
} from 'three';
import { LineSegmentsGeometry } from 'three/addons/lines/LineSegmentsGeometry.js';
import { INFINITELY_SHARP, type MeshTags, type RenderBuffers } from '../core/mesh';
import { PartedAttribute, setVertexAttribute, valuesOf, vertexAttribute } from './parted-attribute';

/**
 * Bytes of index one draw call takes at most: a larger surface or edge
 * list is drawn in parts (the same triangles in the same order), so that
 * each part's index goes to the GPU in a frame of its own (as much as a
 * frame sends: UPLOAD_BYTES_PER_FRAME in shared-renderer.ts).
 */
export const PART_INDEX_BYTES = 4 * 1024 * 1024;

/** `whole` as geometries of at most `per` indices each, sharing its attributes (itself when it fits). */
function partsOf(whole: BufferGeometry, index: Uint32Array, per: number): BufferGeometry[] {
  if (index.length <= per) return [whole];
  const parts: BufferGeometry[] = [];
  for (let start = 0; start < index.length; start += per) {
    const part = new BufferGeometry();
    for (const [name, attribute] of Object.entries(whole.attributes)) part.setAttribute(name, attribute);
    // A view, not a copy: WebGL uploads the view's bytes.
    part.setIndex(new BufferAttribute(index.subarray(start, start + per), 1));
    part.boundingSphere = (whole.boundingSphere as Sphere).clone();
    parts.push(part);
  }
  return parts;
}

/**
 * The colour of a sharpness: amber for a crease that fades within a level,
 * through orange to red at 5 and more, a dark red when infinitely sharp.
 */
export function sharpnessColor(sharpness: number): Color {
  if (sharpness >= INFINITELY_SHARP) return new Color(SHARPNESS_COLORS.infinite);
  const t = Math.min(Math.max(sharpness, 0), 5) / 5;
  return new Color(SHARPNESS_COLORS.weak).lerp(new Color(SHARPNESS_COLORS.strong), t);
}

export const SHARPNESS_COLORS = { weak: '#f59f00', strong: '#e03131', infinite: '#6b0f1a' } as const;

/** Viridis at six stops (0, 0.2, ... 1): dark purple for nothing, yellow for all. */
export const INFLUENCE_STOPS = ['#440154', '#414487', '#2a788e', '#22a884', '#7ad151', '#fde725'] as const;

/** The colour of a value t in [0, 1] on {@link INFLUENCE_STOPS} (clamped). */
export function influenceColor(t: number): Color {
  const x = Math.min(Math.max(Number.isFinite(t) ? t : 0, 0), 1) * (INFLUENCE_STOPS.length - 1);
  const i = Math.min(Math.floor(x), INFLUENCE_STOPS.length - 2);
  return new Color(INFLUENCE_STOPS[i]).lerp(new Color(INFLUENCE_STOPS[i + 1]), x - i);
}

/**
 * Per-vertex colours (three numbers in 0..1 a vertex, as setLevelColors
 * takes them) of `values` on the influence scale, `min` dark and `max`
 * yellow.
 */
export function influenceColors(values: ArrayLike<number>, min: number, max: number): Float32Array {
  const rgb = new Float32Array(3 * values.length);
  for (let v = 0; v < values.length; ++v) {
    const c = influenceColor(max > min ? (values[v] - min) / (max - min) : 0);
    rgb[3 * v] = c.r;
    rgb[3 * v + 1] = c.g;
    rgb[3 * v + 2] = c.b;
  }
  return rgb;
}

/** The points `vertices` of a level, with the colour of its item's sharpness for each (`per` points an item). */
function coloredPoints(positions: Float32Array, vertices: ArrayLike<number>, sharpness: ArrayLike<number>, per: 1 | 2) {
  const xyz = new Float32Array(3 * vertices.length);
  const rgb = new Float32Array(3 * vertices.length);
  for (let i = 0; i < vertices.length; ++i) {
    const v = vertices[i];
    xyz.set(positions.subarray(3 * v, 3 * v + 3), 3 * i);
    const c = sharpnessColor(sharpness[Math.floor(i / per)]);
    rgb.set([c.r, c.g, c.b], 3 * i);
  }
  return { xyz, rgb };
}

/**
 * Draws `parts` (a level's geometry, maybe in parts) with `object`: the
 * first part itself, the others as children sharing its material, made as
 * needed and kept (hidden) for the next level; created in order, so three
 * draws them in order (same material, same depth: by object id).
 */
export function showParts(object: Mesh | LineSegments, parts: readonly BufferGeometry[]): void {
  object.geometry = parts[0];
  for (let i = 1; i < parts.length; i++) {
    let child = object.children[i - 1] as Mesh | LineSegments | undefined;
    if (!child) {
      child =
        object instanceof Mesh ? new Mesh(parts[i], object.material) : new LineSegments(parts[i], object.material);
      child.frustumCulled = false;
      object.add(child);
    }
    child.geometry = parts[i];
    child.visible = true;
  }
  for (const child of object.children.slice(parts.length - 1) as (Mesh | LineSegments)[]) {
    child.visible = false;
    // Lets a dropped level's arrays go.
    child.geometry = NO_GEOMETRY;
  }
}

/** What hidden parts hold (never drawn). */
export const NO_GEOMETRY = new BufferGeometry();

/**
 * Segments above which a level's lines (its polygon edges, the control
 * mesh's, its control-edge curves) are drawn as WebGL's own one-pixel
 * lines over the level's own index (edgeParts, or the curves' index),
 * sharing the surface's positions, instead of fat lines: there they are far
 * less than a pixel apart, faded to a shade, and fat lines would copy every
 * segment's ends on the main thread (hundreds of milliseconds) and send as
 * many bytes again to the GPU.
 */
export const DENSE_LINE_SEGMENTS = 1_000_000;

/** Whether `lines` (an indexed line geometry) has more than {@link DENSE_LINE_SEGMENTS} segments. */
export function denseLines(lines: BufferGeometry): boolean {
  return (lines.index?.count ?? 0) / 2 > DENSE_LINE_SEGMENTS;
}

export class LevelGraphics {
  /** Fanned polygons with the core's smooth vertex normals (flat shading is a material switch). */
  readonly surface: BufferGeometry;
  /** {@link surface} as the view draws it: one geometry, or parts of at most {@link PART_INDEX_BYTES} of index. */
  readonly surfaceParts: BufferGeometry[];
  /** Polygon edges as line segments. */
  readonly edges: BufferGeometry;
  /** {@link edges} in parts, as {@link surfaceParts}. */
  readonly edgeParts: BufferGeometry[];
  /** The marked control edges of this level (null when the core marked none). */
  readonly curves: BufferGeometry | null;
  /**
   * The level's sharp edges as coloured segments a few pixels wide (three's
   * fat lines: WebGL draws its own lines one pixel wide) and its sharp
   * vertices as coloured points (null: none).
   */
  readonly creases: LineSegmentsGeometry | null;
  readonly corners: BufferGeometry | null;
  /** The border edges (of one face) as segments a few pixels wide, drawn with the polygon edges (null: closed). */
  readonly borders: LineSegmentsGeometry | null;
  /**
   * The faces the surface draws. A closed surface hides the faces turned
   * away from the camera behind those turned towards it, so only the latter
   * are drawn (the same picture; software rasterisers, as in headless
   * Chromium, spend a third less on a million triangles); an open one shows
   * both sides.
   */
  readonly side: Side;

  /**
   * `orientation`: +1 (−1) when the level is closed and its faces turn
   * outward (inward); 0 draws both sides.
   */
  constructor(
    buffers: RenderBuffers,
    controlEdges: Uint32Array = new Uint32Array(0),
    orientation: -1 | 0 | 1 = 0,
    tags: MeshTags | null = null,
  ) {
    this.side = orientation > 0 ? FrontSide : orientation < 0 ? BackSide : DoubleSide;
    const position = vertexAttribute(buffers.positions, 3);
    this.surface = new BufferGeometry();
    setVertexAttribute(this.surface, 'position', position);
    this.surface.setIndex(new BufferAttribute(buffers.triangles, 1));
    setVertexAttribute(this.surface, 'normal', vertexAttribute(buffers.normals, 3));
    // The core's sphere: three would otherwise walk every vertex on the main thread, once per geometry.
    const [x, y, z, r] = buffers.boundingSphere;
    const sphere = new Sphere(new Vector3(x, y, z), r);
    this.surface.boundingSphere = sphere;

    this.edges = new BufferGeometry();
    setVertexAttribute(this.edges, 'position', position);
    this.edges.setIndex(new BufferAttribute(buffers.edges, 1));
    this.edges.boundingSphere = sphere.clone();
    // Whole triangles and whole segments per part.
    const perPart = PART_INDEX_BYTES / 4;
    this.surfaceParts = partsOf(this.surface, buffers.triangles, perPart - (perPart % 3));
    this.edgeParts = partsOf(this.edges, buffers.edges, perPart - (perPart % 2));

    this.curves = null;
    if (controlEdges.length > 0) {
      this.curves = new BufferGeometry();
      setVertexAttribute(this.curves, 'position', position);
      this.curves.setIndex(new BufferAttribute(controlEdges, 1));
      this.curves.boundingSphere = sphere.clone();
    }
    this.borders = null;
    if (buffers.borderEdges.length > 0) {
      const xyz = new Float32Array(3 * buffers.borderEdges.length);
      for (const [i, v] of buffers.borderEdges.entries()) xyz.set(buffers.positions.subarray(3 * v, 3 * v + 3), 3 * i);
      this.borders = new LineSegmentsGeometry().setPositions(xyz);
      this.borders.boundingSphere = sphere.clone();
    }
    this.creases = null;
    this.corners = null;
    if (tags && tags.creaseEdges.length > 0) {
      const { xyz, rgb } = coloredPoints(buffers.positions, tags.creaseEdges, tags.creaseSharpness, 2);
      this.creases = new LineSegmentsGeometry().setPositions(xyz).setColors(rgb);
      this.creases.boundingSphere = sphere.clone();
    }
    if (tags && tags.cornerVertices.length > 0) {
      const { xyz, rgb } = coloredPoints(buffers.positions, tags.cornerVertices, tags.cornerSharpness, 1);
      this.corners = new BufferGeometry();
      this.corners.setAttribute('position', new Float32BufferAttribute(xyz, 3));
      this.corners.setAttribute('color', new Float32BufferAttribute(rgb, 3));
      this.corners.boundingSphere = sphere.clone();
    }
  }

  /**
   * Colours the surface per vertex (`rgb`: r g b in 0..1 per vertex), or
   * back to its one colour (null); the view draws them with
   * SceneView.setVertexColors.
   */
  setColors(rgb: Float32Array | null): void {
    // One attribute shared by the surface and its parts, refilled when it fits.
    const color = this.surface.getAttribute('color');
    if (rgb && color && valuesOf(color).length === rgb.length) {
      valuesOf(color).set(rgb);
      color.needsUpdate = true;
      return;
    }
    if (color instanceof PartedAttribute) color.drop();
    // A copy: the next colours of this length are written into it, and `rgb` is its owner's (setLevelColors).
    const attribute = rgb ? vertexAttribute(rgb.slice(), 3) : null;
    for (const geometry of new Set([this.surface, ...this.surfaceParts])) {
      if (attribute) setVertexAttribute(geometry, 'color', attribute);
      else geometry.deleteAttribute('color');
    }
  }

  /** The level's points as drawn (x y z a vertex): change them in place, then call {@link pointsMoved}. */
  get points(): Float32Array {
    return valuesOf(this.surface.getAttribute('position'));
  }

  /** The surface's unit vertex normals (x y z a vertex). */
  get normals(): Float32Array {
    return valuesOf(this.surface.getAttribute('normal'));
  }

  /**
   * Redraws {@link points} after they changed, shaded with `normals` (x y z
   * a vertex), or with the normals of the drawn triangles (null: three's
   * computeVertexNormals, area-weighted, as the core's).
   */
  pointsMoved(normals: Float32Array | null): void {
    if (normals) this.normals.set(normals);
    else {
      // On plain attributes over the same arrays: three reads and writes a parted attribute's values as numbers.
      const scratch = new BufferGeometry();
      scratch.setAttribute('position', new BufferAttribute(this.points, 3));
      scratch.setAttribute('normal', new BufferAttribute(this.normals, 3));
      scratch.setIndex(this.surface.index);
      scratch.computeVertexNormals();
    }
    this.surface.getAttribute('position').needsUpdate = true;
    this.surface.getAttribute('normal').needsUpdate = true;
  }

  /** Bounding sphere of the surface. */
  get boundingSphere(): Sphere {
    return this.surface.boundingSphere as Sphere;
  }

  /** Frees both geometries on the GPU. */
  dispose(): void {
    // Each part's index first (disposing a geometry frees its attributes on the GPU), then the wholes.
    for (const part of [...this.surfaceParts, ...this.edgeParts]) part.dispose();
    this.surface.dispose();
    this.edges.dispose();
    this.curves?.dispose();
    this.creases?.dispose();
    this.corners?.dispose();
    this.borders?.dispose();
  }
}
