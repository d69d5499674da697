/** Shared fixtures access and matchers for the Node tests (tests/unit). */
import { readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { expect } from 'vitest';
import type { Mesh, MeshFacts } from '../../web/core/mesh';
import { parseRuleSetText, type RuleSet } from '../../web/core/rule-set';
import { formatFromFileName, meshFacts, parseMesh } from '../../web/core/subdiv-core';

export const FIXTURES_DIR = join(dirname(fileURLToPath(import.meta.url)), '..', 'fixtures');

/** The rules panel's preset public/rules/NAME.json. */
export function rulePreset(name: string): RuleSet {
  return parseRuleSetText(readFileSync(join(FIXTURES_DIR, '..', '..', 'public', 'rules', `${name}.json`), 'utf8'));
}

/** Text of tests/fixtures/NAME. */
export function fixtureText(name: string): string {
  return readFileSync(join(FIXTURES_DIR, name), 'utf8');
}

/** tests/fixtures/NAME parsed by the core (format from the extension). */
export function loadFixture(name: string): Mesh {
  const format = formatFromFileName(name);
  if (!format) throw new Error(`fixture ${name} is neither .off nor .obj`);
  return parseMesh(fixtureText(name), format);
}

/** A mesh as plain arrays, for the reference implementations in the tests. */
export interface PlainMesh {
  points: [number, number, number][];
  faces: number[][];
}

export function toPlain(mesh: Mesh): PlainMesh {
  const points: [number, number, number][] = [];
  for (let i = 0; i < mesh.positions.length; i += 3) {
    points.push([mesh.positions[i], mesh.positions[i + 1], mesh.positions[i + 2]]);
  }
  const faces: number[][] = [];
  let offset = 0;
  for (const size of mesh.faceSizes) {
    faces.push(Array.from(mesh.faceIndices.subarray(offset, offset + size)));
    offset += size;
  }
  return { points, faces };
}

/** The count fields of the facts that `expected` names are exactly as given. */
export function expectCounts(facts: MeshFacts, expected: Partial<MeshFacts>): void {
  const actual: Partial<MeshFacts> = {};
  for (const key of Object.keys(expected) as (keyof MeshFacts)[]) {
    (actual as Record<string, unknown>)[key] = facts[key];
  }
  expect(actual).toEqual(expected);
}

/** Facts of a mesh through the core. */
export function factsOf(mesh: Mesh): MeshFacts {
  return meshFacts(mesh);
}

function diagonal(points: [number, number, number][]): number {
  const lo = [Infinity, Infinity, Infinity];
  const hi = [-Infinity, -Infinity, -Infinity];
  for (const p of points) {
    for (let a = 0; a < 3; a++) {
      lo[a] = Math.min(lo[a], p[a]);
      hi[a] = Math.max(hi[a], p[a]);
    }
  }
  return Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
}

/**
 * For each point of `expected`, the index of the point of `actual` within
 * `relTol` × (bounding-box diagonal); fails when one is missing or the counts differ.
 */
export function matchPoints(
  actual: [number, number, number][],
  expected: [number, number, number][],
  relTol = 1e-12,
): number[] {
  expect(actual.length).toBe(expected.length);
  const tol = relTol * Math.max(diagonal(expected), 1e-300);
  // A grid of cells much larger than the tolerance and much smaller than the
  // spacing of the points; a point is looked for in its cell and the 26 around.
  const cell = Math.max(tol * 1e4, 1e-300);
  const grid = new Map<string, number[]>();
  const key = (x: number, y: number, z: number) => `${x},${y},${z}`;
  actual.forEach((p, i) => {
    const k = key(Math.floor(p[0] / cell), Math.floor(p[1] / cell), Math.floor(p[2] / cell));
    const list = grid.get(k);
    if (list) list.push(i);
    else grid.set(k, [i]);
  });
  const used = new Uint8Array(actual.length);
  return expected.map((q, j) => {
    const c = q.map((v) => Math.floor(v / cell));
    let best = -1;
    let bestDistance = Infinity;
    for (let dx = -1; dx <= 1; dx++) {
      for (let dy = -1; dy <= 1; dy++) {
        for (let dz = -1; dz <= 1; dz++) {
          for (const i of grid.get(key(c[0] + dx, c[1] + dy, c[2] + dz)) ?? []) {
            const p = actual[i];
            const d = Math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
            if (d < bestDistance) {
              bestDistance = d;
              best = i;
            }
          }
        }
      }
    }
    if (best < 0 || bestDistance > tol || used[best]) {
      expect.fail(`expected point ${j} (${q.join(', ')}) not found within ${tol} (nearest ${bestDistance})`);
    }
    used[best] = 1;
    return best;
  });
}

/** A face as a cyclic sequence starting at its smallest index, so equal faces compare equal. */
function canonicalFace(face: number[]): string {
  let start = 0;
  for (let k = 1; k < face.length; k++) if (face[k] < face[start]) start = k;
  return [...face.slice(start), ...face.slice(0, start)].join(' ');
}

/** Same points (to `relTol`) and the same oriented faces, whatever the numbering. */
export function expectSameMesh(actual: Mesh, expected: PlainMesh, relTol = 1e-12): void {
  const plain = toPlain(actual);
  const map = matchPoints(plain.points, expected.points, relTol);
  const expectedFaces = expected.faces.map((f) => canonicalFace(f.map((v) => map[v]))).sort();
  const actualFaces = plain.faces.map(canonicalFace).sort();
  expect(actualFaces).toEqual(expectedFaces);
}

/** Same number of points, each within `relTol` of the other mesh's point of the same index. */
export function expectSamePoints(actual: Mesh, expected: Mesh, relTol = 1e-12): void {
  expect(actual.positions.length).toBe(expected.positions.length);
  const scale = Math.max(...Array.from(expected.positions, Math.abs), 1e-300);
  for (let i = 0; i < expected.positions.length; i++) {
    if (Math.abs(actual.positions[i] - expected.positions[i]) > relTol * scale) {
      expect.fail(`coordinate ${i}: ${actual.positions[i]} differs from ${expected.positions[i]}`);
    }
  }
}
