/**
 * Exact counts of √3 and Doo-Sabin on open meshes, levels 1-3, worked out
 * from each refinement's construction on the previous level's mesh.
 */
import { beforeAll, describe, expect, it } from 'vitest';
import { initNode } from '../../web/core/init-node';
import type { Mesh } from '../../web/core/mesh';
import { meshFacts, subdivide } from '../../web/core/subdiv-core';
import { loadFixture } from './test-helpers';

beforeAll(async () => {
  await initNode();
});

interface Topology {
  V: number;
  E: number;
  F: number;
  /** Border edges (= border vertices on a manifold mesh). */
  B: number;
  /** Border vertices with one face (valence 2). */
  ears: number;
  /** Border vertices with three or more faces (valence 4 or more). */
  fans: number;
}

function topology(mesh: Mesh): Topology {
  const V = mesh.positions.length / 3;
  const uses = new Map<string, number>();
  const valence = new Map<number, Set<number>>();
  let offset = 0;
  for (const size of mesh.faceSizes) {
    for (let k = 0; k < size; k++) {
      const a = mesh.faceIndices[offset + k];
      const b = mesh.faceIndices[offset + ((k + 1) % size)];
      const key = a < b ? `${a} ${b}` : `${b} ${a}`;
      uses.set(key, (uses.get(key) ?? 0) + 1);
      for (const [p, q] of [
        [a, b],
        [b, a],
      ]) {
        const set = valence.get(p) ?? new Set<number>();
        set.add(q);
        valence.set(p, set);
      }
    }
    offset += size;
  }
  const border = new Set<number>();
  let B = 0;
  for (const [key, n] of uses) {
    if (n === 1) {
      B++;
      for (const v of key.split(' ')) border.add(Number(v));
    }
  }
  let ears = 0;
  let fans = 0;
  for (const v of border) {
    const d = valence.get(v)?.size ?? 0;
    if (d === 2) ears++;
    if (d >= 4) fans++;
  }
  return { V, E: uses.size, F: mesh.faceSizes.length, B, ears, fans };
}

function counts(mesh: Mesh) {
  const f = meshFacts(mesh);
  return { vertices: f.vertices, edges: f.edges, faces: f.faces };
}

describe('√3 on open meshes', () => {
  // A centre per face and the old edges flipped; CGAL refines the border on
  // every second step: each border edge trisected, its triangle split in three.
  it.each(['disk-tri.off', 'mixed-open.off', 'grid-open.off'])('%s, levels 1-3 in one call', (fixture) => {
    // Level 0 with triangulate: the quads and the pentagon cut into triangles.
    const input = subdivide(loadFixture(fixture), { scheme: 'sqrt3', levels: 0, triangulate: true });
    expect(meshFacts(input).triangles).toBe(meshFacts(input).faces);
    let previous = input;
    for (let level = 1; level <= 3; level++) {
      const t = topology(previous);
      const b = level % 2 === 0 ? t.B : 0;
      const out = subdivide(input, { scheme: 'sqrt3', levels: level });
      expect(counts(out)).toEqual({ vertices: t.V + t.F + b, edges: t.E + 3 * t.F + b, faces: 3 * t.F });
      expect(meshFacts(out).boundaries).toBe(1);
      previous = out;
    }
  });

  it('literal numbers on the triangle fan (7 vertices, 6 triangles, 6 border edges)', () => {
    const disk = loadFixture('disk-tri.off');
    const at = (levels: number) => counts(subdivide(disk, { scheme: 'sqrt3', levels }));
    expect(at(1)).toEqual({ vertices: 13, edges: 30, faces: 18 });
    expect(at(2)).toEqual({ vertices: 37, edges: 90, faces: 54 });
    expect(at(3)).toEqual({ vertices: 91, edges: 252, faces: 162 });
  });
});

describe('Doo-Sabin on open meshes', () => {
  // An F-face per face (a valence-2 border corner gives its face two points),
  // an E-face per interior edge, a V-face per interior vertex and per border
  // vertex with 3 or more faces; the border is cut as Chaikin cuts a polygon.
  it.each(['grid-open.off', 'mixed-open.off', 'disk-tri.off'])('%s, levels 1-3', (fixture) => {
    const base = loadFixture(fixture);
    let previous = base;
    for (let level = 1; level <= 3; level++) {
      const t = topology(previous);
      const out = subdivide(base, { scheme: 'doo-sabin', levels: level });
      expect(counts(out)).toEqual({
        vertices: 2 * t.E - t.B + t.ears,
        edges: 4 * t.E - 3 * t.B + t.ears + t.fans,
        faces: t.F + (t.E - t.B) + (t.V - t.B) + t.fans,
      });
      expect(topology(out).B).toBe(2 * t.B);
      previous = out;
    }
  });

  it('literal numbers on the 3 x 3 grid', () => {
    const grid = loadFixture('grid-open.off');
    // 9 F-faces, 12 E-faces (interior edges), 4 V-faces (interior vertices);
    // 12 border edges become 24; the 4 corners are cut.
    expect(counts(subdivide(grid, { scheme: 'doo-sabin', levels: 1 }))).toEqual({ vertices: 40, edges: 64, faces: 25 });
  });
});
