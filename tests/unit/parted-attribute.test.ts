/**
 * A level's vertex attributes larger than a frame's upload are parted
 * attributes (three's GLBufferAttribute on a buffer the shared renderer
 * fills in parts) that keep their array: what reads and moves a level's
 * points works on them as on plain ones. The upload itself needs WebGL:
 * tests/e2e/render-and-export.spec.ts draws such levels.
 */
import { BufferAttribute, BufferGeometry } from 'three';
import { describe, expect, it } from 'vitest';
import type { RenderBuffers } from '../../web/core/mesh';
import { LevelGraphics } from '../../web/render/level-graphics';
import {
  HURRY_WITHIN_MS,
  PARTED_ATTRIBUTE_BYTES,
  PartedAttribute,
  vertexAttribute,
} from '../../web/render/parted-attribute';

/** A wavy sheet of `n` × 2 quads ((n + 1) · 3 vertices), fanned into triangles; normals all (0, 0, 1) until moved. */
function wavySheet(n: number): RenderBuffers {
  const positions = new Float32Array(9 * (n + 1));
  for (let i = 0; i <= n; i++)
    for (let j = 0; j < 3; j++) positions.set([i / n, j, Math.sin((i * j) / 50)], 3 * (3 * i + j));
  const triangles = new Uint32Array(12 * n);
  for (let i = 0; i < n; i++)
    for (let j = 0; j < 2; j++) {
      const [a, b, c, d] = [3 * i + j, 3 * i + j + 3, 3 * i + j + 4, 3 * i + j + 1];
      triangles.set([a, b, c, a, c, d], 12 * i + 6 * j);
    }
  return {
    positions,
    boundingSphere: new Float32Array([0.5, 1, 0, 2]),
    normals: new Float32Array(positions.length).map((_, i) => (i % 3 === 2 ? 1 : 0)),
    triangles,
    edges: new Uint32Array(0),
    triangleFace: new Uint32Array(triangles.length / 3).map((_, t) => t >> 1),
    borderEdges: new Uint32Array(0),
  };
}

describe('vertexAttribute', () => {
  it('is a plain attribute up to PARTED_ATTRIBUTE_BYTES and a parted one past it, over the same array', () => {
    const fits = new Float32Array(PARTED_ATTRIBUTE_BYTES / 4);
    expect(vertexAttribute(fits, 3)).toBeInstanceOf(BufferAttribute);
    const over = new Float32Array(PARTED_ATTRIBUTE_BYTES / 4 + 3);
    const parted = vertexAttribute(over, 3);
    expect(parted).toBeInstanceOf(PartedAttribute);
    expect(parted.array).toBe(over);
    expect([parted.itemSize, parted.count]).toEqual([3, over.length / 3]);
  });

  it('a parted attribute is complete only with a buffer holding all of it; a change sends it again', () => {
    const parted = new PartedAttribute(new Float32Array(30), 3);
    expect(parted.complete).toBe(false);
    parted.buffer = {} as WebGLBuffer;
    parted.sent = 60;
    expect(parted.complete).toBe(false);
    parted.sent = 120;
    expect(parted.complete).toBe(true);
    const version = parted.version;
    parted.needsUpdate = true;
    expect([parted.sent, parted.version, parted.complete, parted.hurried]).toEqual([0, version + 1, false, false]);
  });

  it('changed again before its last change was all sent, it is hurried: sent whole, not in parts', () => {
    const parted = new PartedAttribute(new Float32Array(30), 3);
    // Without a buffer, nothing was sent yet: a change is no reason to hurry.
    parted.needsUpdate = true;
    expect(parted.hurried).toBe(false);
    parted.buffer = {} as WebGLBuffer;
    parted.sent = 120;
    parted.needsUpdate = true;
    expect(parted.hurried).toBe(false);
    // Split's blend: the next frame's change comes while the first part of this one is on its way.
    parted.sent = 48;
    parted.needsUpdate = true;
    expect([parted.hurried, parted.sent]).toEqual([true, 0]);
    // Or just after all of it went (as SharedRenderer records): the next frame's change is hurried too.
    parted.hurried = false;
    parted.sent = 120;
    parted.completedAt = performance.now();
    parted.needsUpdate = true;
    expect(parted.hurried).toBe(true);
    parted.hurried = false;
    parted.sent = 120;
    parted.completedAt = performance.now() - HURRY_WITHIN_MS - 1;
    parted.needsUpdate = true;
    expect(parted.hurried).toBe(false);
  });
});

describe('LevelGraphics with parted attributes', () => {
  // 120,000 vertices: 1.44 MB of points; 400,000: 4.8 MB, parted.
  const small = wavySheet(39_999);
  const large = wavySheet(133_332);

  it('parts the points and normals of a large level only, shared by its surface parts and edges', () => {
    const graphics = new LevelGraphics(large);
    const position = graphics.surface.getAttribute('position') as unknown;
    expect(position).toBeInstanceOf(PartedAttribute);
    expect(graphics.surface.getAttribute('normal') as unknown).toBeInstanceOf(PartedAttribute);
    expect(graphics.points).toBe(large.positions);
    expect(graphics.normals).toBe(large.normals);
    expect(graphics.surfaceParts.length).toBeGreaterThan(1);
    for (const part of [...graphics.surfaceParts, graphics.edges])
      expect(part.getAttribute('position') as unknown).toBe(position);
    expect(new LevelGraphics(small).surface.getAttribute('position')).toBeInstanceOf(BufferAttribute);
  });

  it('moved points get the normals three works out for the same triangles, and are marked for upload', () => {
    const buffers = wavySheet(133_332);
    const graphics = new LevelGraphics(buffers);
    const position = graphics.surface.getAttribute('position') as BufferAttribute;
    const normal = graphics.surface.getAttribute('normal') as BufferAttribute;
    const versions = [position.version, normal.version];
    for (let i = 2; i < graphics.points.length; i += 3) graphics.points[i] *= -0.5;
    graphics.pointsMoved(null);
    // three's own normals of a plain geometry with copies of the moved points.
    const plain = new BufferGeometry();
    plain.setAttribute('position', new BufferAttribute(Float32Array.from(graphics.points), 3));
    plain.setIndex(new BufferAttribute(buffers.triangles, 1));
    plain.computeVertexNormals();
    const expected = plain.getAttribute('normal').array as Float32Array;
    // Compared by a loop: toEqual over 1.2 M numbers takes seconds.
    expect(graphics.normals.length).toBe(expected.length);
    expect(graphics.normals.findIndex((x, i) => x !== expected[i])).toBe(-1);
    // Not the normals before (all (0, 0, 1)): vertex 1's row slopes along x.
    expect(Math.abs(graphics.normals[3])).toBeGreaterThan(1e-3);
    expect([position.version, normal.version]).toEqual([versions[0] + 1, versions[1] + 1]);

    const own = new Float32Array(graphics.normals.length).fill(0.25);
    graphics.pointsMoved(own);
    expect(graphics.normals.every((x) => x === 0.25)).toBe(true);
    expect(normal.version).toBe(versions[1] + 2);
  });

  it('per-vertex colours of a large level are parted too, refilled in place', () => {
    const graphics = new LevelGraphics(wavySheet(133_332));
    const rgb = new Float32Array(graphics.points.length).fill(0.5);
    graphics.setColors(rgb);
    const color = graphics.surface.getAttribute('color') as unknown as PartedAttribute;
    expect(color).toBeInstanceOf(PartedAttribute);
    for (const part of graphics.surfaceParts) expect(part.getAttribute('color') as unknown).toBe(color);
    // The attribute holds a copy: the owner's colours stay as they are when the next ones are written.
    expect(color.array).not.toBe(rgb);
    color.sent = color.array.byteLength;
    graphics.setColors(new Float32Array(rgb.length).fill(0.75));
    expect(graphics.surface.getAttribute('color') as unknown).toBe(color);
    expect([color.array[7], color.sent, rgb[7]]).toEqual([0.75, 0, 0.5]);
    expect(color.dropped).toBe(false);
    // Taken off: dropped, so that the shared renderer frees its buffer (the geometry lives on).
    graphics.setColors(null);
    expect(graphics.surface.getAttribute('color')).toBeUndefined();
    expect(color.dropped).toBe(true);
  });
});
