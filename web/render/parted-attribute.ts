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

/** WebGL's FLOAT (three's GLBufferAttribute takes the GL type). */
const GL_FLOAT = 0x1406;

export class PartedAttribute extends GLBufferAttribute {
  /** The values, as the CPU keeps them. */
  readonly array: Float32Array;
  /** Bytes of {@link array} on the GPU, from the start (the buffer is complete at array.byteLength). */
  sent = 0;

  constructor(array: Float32Array, itemSize: number) {
    // No buffer yet: SharedRenderer.upload makes it before the first draw.
    super(null as unknown as WebGLBuffer, GL_FLOAT, itemSize, 4, array.length / itemSize);
    this.array = array;
  }

  /** Whether the GPU holds all of {@link array}. */
  get complete(): boolean {
    return this.buffer !== null && this.sent === this.array.byteLength;
  }

  /** Marks {@link array} changed: it goes to the GPU again, in parts, before the next draw. */
  override set needsUpdate(value: boolean) {
    if (!value) return;
    this.sent = 0;
    this.version++;
  }
}

/** A level's vertex attribute of `itemSize` floats a vertex: in parts when larger than {@link PARTED_ATTRIBUTE_BYTES}. */
export function vertexAttribute(array: Float32Array, itemSize: number): BufferAttribute | PartedAttribute {
  return array.byteLength > PARTED_ATTRIBUTE_BYTES
    ? new PartedAttribute(array, itemSize)
    : new BufferAttribute(array, itemSize);
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
