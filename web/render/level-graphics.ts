/**
 * GPU geometry of one level, built from the core's render buffers: a
 * triangle geometry for the surface and a line geometry of the *polygon*
 * edges (so quads are drawn as quads, never as triangle pairs). Both share
 * one position attribute. Call dispose() when the level is dropped.
 */
import { BufferAttribute, BufferGeometry, type Sphere } from 'three';
import type { RenderBuffers } from '../core/mesh';

export class LevelGraphics {
  /** Fanned polygons with the core's smooth vertex normals (flat shading is a material switch). */
  readonly surface: BufferGeometry;
  /** Polygon edges as line segments. */
  readonly edges: BufferGeometry;
  /** The marked control edges of this level (null when the core marked none). */
  readonly curves: BufferGeometry | null;

  constructor(buffers: RenderBuffers, controlEdges: Uint32Array = new Uint32Array(0)) {
    const position = new BufferAttribute(buffers.positions, 3);
    this.surface = new BufferGeometry();
    this.surface.setAttribute('position', position);
    this.surface.setIndex(new BufferAttribute(buffers.triangles, 1));
    this.surface.setAttribute('normal', new BufferAttribute(buffers.normals, 3));
    this.surface.computeBoundingSphere();

    this.edges = new BufferGeometry();
    this.edges.setAttribute('position', position);
    this.edges.setIndex(new BufferAttribute(buffers.edges, 1));

    this.curves = null;
    if (controlEdges.length > 0) {
      this.curves = new BufferGeometry();
      this.curves.setAttribute('position', position);
      this.curves.setIndex(new BufferAttribute(controlEdges, 1));
    }
  }

  /** Bounding sphere of the surface. */
  get boundingSphere(): Sphere {
    if (!this.surface.boundingSphere) this.surface.computeBoundingSphere();
    return this.surface.boundingSphere as Sphere;
  }

  /** Frees both geometries on the GPU. */
  dispose(): void {
    this.surface.dispose();
    this.edges.dispose();
    this.curves?.dispose();
  }
}
