/**
 * Vertex attributes that go to the GPU a few megabytes at a time. three.js
 * gives WebGL a BufferAttribute's whole array in the call that first draws
 * it, and Chromium copies that array to the GPU process within the call: a
 * level of 3.6 M vertices has 43 MB of positions and as many of normals, a
 * main-thread task of 100–150 ms each with a software renderer (0.5 s at
 * 17 M vertices). A {@link PartedAttribute} is three's GLBufferAttribute on
 * a buffer the shared renderer makes at its size and fills in parts, one
 * part an animation frame (SharedRenderer.upload); it keeps its array, so
 * what reads a level's points (picking, fitting, fat lines, Split's blend)
 * reads them as from a BufferAttribute.
 */
import { BufferAttribute, type BufferGeometry, GLBufferAttribute } from 'three';

/** Bytes above which a level's vertex attribute is sent in parts (as much as a frame sends: UPLOAD_BYTES_PER_FRAME). */
export const PARTED_ATTRIBUTE_BYTES = 4 * 1024 * 1024;

/** A parted attribute changed this soon after it was all sent is changing every frame: sent whole (PartedAttribute.hurried). */
export const HURRY_WITHIN_MS = 500;

/** WebGL's FLOAT (three's GLBufferAttribute takes the GL type). */
const GL_FLOAT = 0x1406;

export class PartedAttribute extends GLBufferAttribute {
  /** The values, as the CPU keeps them. */
  readonly array: Float32Array;
  /** Bytes of {@link array} on the GPU, from the start (the buffer is complete at array.byteLength). */
  sent = 0;
  /**
   * Changed again before its last change was all sent, or within
   * {@link HURRY_WITHIN_MS} of it (Split's blend, its slider: a change
   * every frame): the next upload sends it whole, as a plain attribute is,
   * since parts would never catch up.
   */
  hurried = false;
  /** performance.now() when the GPU last got all of {@link array} (SharedRenderer). */
  completedAt = Number.NEGATIVE_INFINITY;
  /** Taken off its geometries for good ({@link drop}): the renderer frees its buffer. */
  dropped = false;
  /** Counts the changes of {@link array} ({@link needsUpdate}); `version` also counts new buffers. */
  changes = 0;

  constructor(array: Float32Array, itemSize: number) {
    // No buffer yet: SharedRenderer.upload makes it before the first draw.
    super(null as unknown as WebGLBuffer, GL_FLOAT, itemSize, 4, array.length / itemSize);
    this.array = array;
  }

  /** Whether the GPU holds all of {@link array}. */
  get complete(): boolean {
    return this.buffer !== null && this.sent === this.array.byteLength;
  }

  /** Marks {@link array} changed: it goes to the GPU again, in parts (or whole when {@link hurried}), before the next draw. */
  override set needsUpdate(value: boolean) {
    if (!value) return;
    if (
      this.buffer !== null &&
      (this.sent < this.array.byteLength || performance.now() - this.completedAt < HURRY_WITHIN_MS)
    )
      this.hurried = true;
    this.sent = 0;
    this.version++;
    this.changes++;
  }

  /**
   * Says the attribute was taken off its geometries while they live on
   * (three frees a buffer when its geometry is disposed, not when an
   * attribute is deleted): the shared renderer frees its buffer and lets go
   * of it.
   */
  drop(): void {
    this.dropped = true;
  }
}

/** A level's vertex attribute of `itemSize` floats a vertex: in parts when larger than {@link PARTED_ATTRIBUTE_BYTES}. */
export function vertexAttribute(array: Float32Array, itemSize: number): BufferAttribute | PartedAttribute {
  return array.byteLength > PARTED_ATTRIBUTE_BYTES
    ? new PartedAttribute(array, itemSize)
    : new BufferAttribute(array, itemSize);
}

/** Counts the changes of a vertex attribute's values (a plain attribute's version counts only those). */
export function changesOf(attribute: BufferAttribute | PartedAttribute): number {
  return attribute instanceof PartedAttribute ? attribute.changes : attribute.version;
}

/** The values of a vertex attribute made by {@link vertexAttribute} (or any BufferAttribute). */
export function valuesOf(attribute: { readonly array: unknown }): Float32Array {
  return attribute.array as Float32Array;
}

/**
 * Sets `attribute` (made by {@link vertexAttribute}) as `name` of
 * `geometry`. three's types take a GLBufferAttribute only on a geometry
 * typed for it, and the level's geometries go to code typed for plain ones,
 * which reads a parted attribute's `array`, `version` and `needsUpdate` only
 * (as the functions here do).
 */
export function setVertexAttribute(
  geometry: BufferGeometry,
  name: string,
  attribute: BufferAttribute | PartedAttribute,
): void {
  geometry.setAttribute(name, attribute as BufferAttribute);
}
