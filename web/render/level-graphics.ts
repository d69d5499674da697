/**
 * GPU geometry of one level, built from the core's render buffers: a
 * triangle geometry for the surface and a line geometry of the *polygon*
 * edges (so quads are drawn as quads, never as triangle pairs). Both share
 * one position attribute. Call dispose() when the level is dropped.
 */
import { BackSide, BufferAttribute, BufferGeometry, DoubleSide, FrontSide, type Side, Sphere, Vector3 } from 'three';
import type { RenderBuffers } from '../core/mesh';

export class LevelGraphics {
  /** Fanned polygons with the core's smooth vertex normals (flat shading is a material switch). */
  readonly surface: BufferGeometry;
  /** Polygon edges as line segments. */
  readonly edges: BufferGeometry;
  /** The marked control edges of this level (null when the core marked none). */
  readonly curves: BufferGeometry | null;
  /**
   * The faces the surface draws. A closed surface hides the faces turned
   * away from the camera behind those turned towards it, so only the latter
   * are drawn (the same picture; software rasterisers, as in headless
   * Chromium, spend a third less on a million triangles); an open one shows
   * both sides.
   */
  readonly side: Side;

  /**
   * `signedVolume`: a closed level's signed volume (positive: normals point
   * out), 0 for an open level, whose faces are drawn on both sides.
   */
  constructor(buffers: RenderBuffers, controlEdges: Uint32Array = new Uint32Array(0), signedVolume = 0) {
    this.side = signedVolume > 0 ? FrontSide : signedVolume < 0 ? BackSide : DoubleSide;
    const position = new BufferAttribute(buffers.positions, 3);
    this.surface = new BufferGeometry();
    this.surface.setAttribute('position', position);
    this.surface.setIndex(new BufferAttribute(buffers.triangles, 1));
    this.surface.setAttribute('normal', new BufferAttribute(buffers.normals, 3));
    // The core's sphere: three would otherwise walk every vertex on the main thread, once per geometry.
    const [x, y, z, r] = buffers.boundingSphere;
    const sphere = new Sphere(new Vector3(x, y, z), r);
    this.surface.boundingSphere = sphere;

    this.edges = new BufferGeometry();
    this.edges.setAttribute('position', position);
    this.edges.setIndex(new BufferAttribute(buffers.edges, 1));
    this.edges.boundingSphere = sphere.clone();

    this.curves = null;
    if (controlEdges.length > 0) {
      this.curves = new BufferGeometry();
      this.curves.setAttribute('position', position);
      this.curves.setIndex(new BufferAttribute(controlEdges, 1));
      this.curves.boundingSphere = sphere.clone();
    }
  }

  /** Bounding sphere of the surface. */
  get boundingSphere(): Sphere {
    return this.surface.boundingSphere as Sphere;
  }

  /** Frees both geometries on the GPU. */
  dispose(): void {
    this.surface.dispose();
    this.edges.dispose();
    this.curves?.dispose();
  }
}
