/**
 * ViewLines: a level's polygon edges and cage are fat lines (the line-width
 * setting applies) up to DENSE_LINE_SEGMENTS segments, and past that WebGL's
 * own lines over the level's index parts, with no copy of their ends.
 */
import { describe, expect, it } from 'vitest';
import type { RenderBuffers } from '../../web/core/mesh';
import { DENSE_LINE_SEGMENTS, LevelGraphics, PART_INDEX_BYTES } from '../../web/render/level-graphics';
import { ViewLines } from '../../web/render/view-lines';

/** A strip of `n` quads (2n + 2 vertices): 3n + 1 edges, fanned into 2n triangles. */
function quadStrip(n: number): RenderBuffers {
  const positions = new Float32Array(3 * (2 * n + 2));
  for (let i = 0; i <= n; i++) {
    positions.set([i, 0, 0], 6 * i);
    positions.set([i, 1, 0], 6 * i + 3);
  }
  const triangles = new Uint32Array(6 * n);
  const edges = new Uint32Array(2 * (3 * n + 1));
  for (let i = 0; i < n; i++) {
    const [a, b, c, d] = [2 * i, 2 * i + 2, 2 * i + 3, 2 * i + 1];
    triangles.set([a, b, c, a, c, d], 6 * i);
    edges.set([a, b, d, c, a, d], 6 * i);
  }
  edges.set([2 * n, 2 * n + 1], 6 * n);
  return {
    positions,
    boundingSphere: new Float32Array([n / 2, 0.5, 0, n]),
    normals: new Float32Array(positions.length).fill(0).map((_, i) => (i % 3 === 2 ? 1 : 0)),
    triangles,
    edges,
    triangleFace: new Uint32Array(2 * n).map((_, i) => i >> 1),
    borderEdges: new Uint32Array(0),
  };
}

const COLORS = { edges: '#222222', control: '#e8590c', curves: '#1c7ed6' };
const opacity = { edges: 0.4, control: 0.7 };

describe('ViewLines', () => {
  it('draws a level of up to a million edges as fat lines, with the width setting', () => {
    const sparse = new LevelGraphics(quadStrip(1000));
    const lines = new ViewLines(COLORS);
    lines.edges.visible = true;
    lines.control.visible = true;
    lines.style(2, sparse, sparse, opacity, []);
    expect(lines.thinEdges.visible).toBe(false);
    expect(lines.thinControl.visible).toBe(false);
    // 3001 segments, each end copied: 6 numbers a segment.
    expect(lines.edges.geometry.getAttribute('instanceStart').count).toBe(3001);
    expect(lines.edges.material.linewidth).toBeGreaterThan(1);
    expect(lines.edges.material.opacity).toBe(0.4);
    expect(lines.control.material.opacity).toBe(0.7);
    // The same level's edges and cage: one fat geometry, made once.
    expect(lines.control.geometry).toBe(lines.edges.geometry);
    expect(lines.geometries(sparse, sparse)).toEqual([lines.edges.geometry, lines.edges.geometry]);
  });

  it('draws a denser level with thin lines over its own index parts, its fat lines empty', () => {
    const n = Math.ceil(DENSE_LINE_SEGMENTS / 3) + 1;
    const dense = new LevelGraphics(quadStrip(n));
    expect(dense.edges.index?.count).toBe(2 * (3 * n + 1));
    // More than one part: 8 MB of index a part.
    expect(dense.edgeParts.length).toBe(Math.ceil((8 * (3 * n + 1)) / PART_INDEX_BYTES));
    const sparse = new LevelGraphics(quadStrip(10));
    const lines = new ViewLines(COLORS);
    lines.edges.visible = true;
    lines.control.visible = true;
    lines.style(1, dense, sparse, opacity, []);
    expect(lines.thinEdges.visible).toBe(true);
    expect(lines.thinEdges.geometry).toBe(dense.edgeParts[0]);
    expect(lines.thinEdges.children.map((c) => (c as typeof lines.thinEdges).geometry)).toEqual(
      dense.edgeParts.slice(1),
    );
    expect(lines.thinEdges.material.opacity).toBe(0.4);
    expect(lines.edges.geometry.getAttribute('instanceStart')).toBeUndefined();
    // The cage of ten quads stays fat.
    expect(lines.thinControl.visible).toBe(false);
    expect(lines.control.geometry.getAttribute('instanceStart').count).toBe(31);
    // The draw needs the index parts (positions are the surface's), not copied ends.
    expect(lines.geometries(dense, sparse)).toEqual([...dense.edgeParts, lines.control.geometry]);

    // Back to a sparse level: the thin lines let the dense one go.
    lines.style(1, sparse, sparse, opacity, []);
    expect(lines.thinEdges.visible).toBe(false);
    expect(lines.thinEdges.geometry.index).toBeNull();
    expect(lines.thinEdges.children.every((c) => (c as typeof lines.thinEdges).geometry.index === null)).toBe(true);
    expect(lines.edges.geometry.getAttribute('instanceStart').count).toBe(31);
  });

  it('dense control-edge curves are thin lines over their own index', () => {
    const n = Math.ceil(DENSE_LINE_SEGMENTS / 3) + 1;
    const buffers = quadStrip(n);
    // Every edge marked: as many curve segments as edges.
    const dense = new LevelGraphics(buffers, buffers.edges.slice());
    const lines = new ViewLines(COLORS);
    lines.edges.visible = false;
    lines.control.visible = false;
    lines.curves.visible = true;
    lines.style(1, dense, null, opacity, []);
    expect(lines.thinCurves.visible).toBe(true);
    expect(lines.thinCurves.geometry).toBe(dense.curves);
    expect(lines.curves.geometry.getAttribute('instanceStart')).toBeUndefined();
    expect(lines.geometries(dense, null)).toEqual([dense.curves]);
    // A few marked edges stay fat.
    const sparse = new LevelGraphics(buffers, buffers.edges.slice(0, 20));
    lines.style(1, sparse, null, opacity, []);
    expect(lines.thinCurves.visible).toBe(false);
    expect(lines.curves.geometry.getAttribute('instanceStart').count).toBe(10);
  });

  it('hidden lines draw nothing, dense or not', () => {
    const dense = new LevelGraphics(quadStrip(Math.ceil(DENSE_LINE_SEGMENTS / 3) + 1));
    const lines = new ViewLines(COLORS);
    lines.edges.visible = false;
    lines.control.visible = false;
    lines.curves.visible = false;
    lines.style(1, dense, dense, opacity, []);
    expect(lines.thinEdges.visible).toBe(false);
    expect(lines.thinControl.visible).toBe(false);
    expect(lines.thinCurves.visible).toBe(false);
    expect(lines.geometries(dense, dense)).toEqual([]);
  });
});
