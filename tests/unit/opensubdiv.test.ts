/**
 * The WASM core's creasing against OpenSubdiv, under Node: each tagged
 * fixture (and a few untagged ones, where OpenSubdiv's edge-only border is
 * CGAL's rule) refined to levels 1–3, one step at a time as the app does,
 * with both crease methods and, on the quad patch, each border mode. The
 * reference is build/native/osd_reference (OpenSubdiv 3.5's Far, numbered
 * as SubdivLab numbers; built by `setup.mjs --native`, which `npm test`
 * runs first). Points must agree to 1e-12, the hole faces exactly.
 */
import { execFileSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { join } from 'node:path';
import { beforeAll, describe, expect, it } from 'vitest';
import { initNode } from '../../web/core/init-node';
import type { BoundaryInterpolation, CreaseMethod, Mesh } from '../../web/core/mesh';
import { subdivide } from '../../web/core/subdiv-core';
import { FIXTURES_DIR, loadFixture } from './test-helpers';

const OSD_REFERENCE = join(FIXTURES_DIR, '..', '..', 'build', 'native', 'osd_reference');

beforeAll(async () => {
  await initNode();
});

interface Reference {
  levels: { positions: number[]; holes: number[][] }[];
}

interface Case {
  fixture: string;
  scheme: 'catmull-clark' | 'loop';
  creaseMethod?: CreaseMethod;
  boundary?: BoundaryInterpolation;
}

function opensubdiv(c: Case, levels: number): Reference {
  if (!existsSync(OSD_REFERENCE)) {
    throw new Error(`${OSD_REFERENCE} is missing: build it with node scripts/setup.mjs --native (needs libosd-dev)`);
  }
  const args = ['--scheme', c.scheme, '--levels', String(levels)];
  if (c.creaseMethod) args.push('--crease-method', c.creaseMethod);
  if (c.boundary) args.push('--boundary', c.boundary);
  args.push(join(FIXTURES_DIR, c.fixture));
  return JSON.parse(execFileSync(OSD_REFERENCE, args, { encoding: 'utf8', maxBuffer: 64 << 20 }));
}

/** The hole faces of `mesh` as vertex cycles from the smallest, sorted. */
function holeCycles(mesh: Mesh): string[] {
  const starts: number[] = [];
  let o = 0;
  for (const size of mesh.faceSizes) {
    starts.push(o);
    o += size;
  }
  return Array.from(mesh.tags?.holes ?? [], (f) => {
    const face = Array.from(mesh.faceIndices.subarray(starts[f], starts[f] + mesh.faceSizes[f]));
    const first = face.indexOf(Math.min(...face));
    return JSON.stringify([...face.slice(first), ...face.slice(0, first)]);
  }).sort();
}

const CASES: Case[] = [];
for (const creaseMethod of ['uniform', 'chaikin'] as const) {
  CASES.push(
    { fixture: 'cube-creased.obj', scheme: 'catmull-clark', creaseMethod },
    { fixture: 'torus-holed.obj', scheme: 'catmull-clark', creaseMethod },
    { fixture: 'tetra-crease.obj', scheme: 'loop', creaseMethod },
    { fixture: '../../public/meshes/cube-creased.obj', scheme: 'catmull-clark', creaseMethod },
  );
}
for (const boundary of ['edge', 'edge-and-corner', 'none'] as const)
  CASES.push({ fixture: 'quad-patch-corners.obj', scheme: 'catmull-clark', boundary });
// Untagged: OpenSubdiv's default edge-only border is CGAL's rule.
CASES.push(
  { fixture: 'grid-open.off', scheme: 'catmull-clark' },
  { fixture: 'disk-tri.off', scheme: 'loop' },
  { fixture: 'octahedron.off', scheme: 'loop' },
);

describe('the WASM core equals OpenSubdiv on tagged meshes, levels 1-3', () => {
  for (const c of CASES) {
    const name = `${c.fixture.replace('../../public/meshes/', 'sample ')} ${c.scheme}${c.creaseMethod ? ` ${c.creaseMethod}` : ''}${
      c.boundary ? ` border ${c.boundary}` : ''
    }`;
    it(name, () => {
      const reference = opensubdiv(c, 3);
      let mesh = loadFixture(c.fixture);
      for (let level = 1; level <= 3; ++level) {
        mesh = subdivide(mesh, {
          scheme: c.scheme,
          levels: 1,
          startLevel: level - 1,
          ...(c.creaseMethod ? { creaseMethod: c.creaseMethod } : {}),
          ...(c.boundary ? { boundary: c.boundary } : {}),
        });
        const want = reference.levels[level - 1];
        expect(mesh.positions.length, `level ${level} vertices`).toBe(want.positions.length);
        let worst = 0;
        for (let i = 0; i < want.positions.length; ++i) {
          const error = Math.abs(mesh.positions[i] - want.positions[i]) / Math.max(1, Math.abs(want.positions[i]));
          worst = Math.max(worst, error);
        }
        expect(worst, `level ${level}: largest difference from OpenSubdiv`).toBeLessThan(1e-12);
        expect(holeCycles(mesh), `level ${level} holes`).toEqual(want.holes.map((h) => JSON.stringify(h)).sort());
      }
    });
  }

  it('and the comparison would notice a difference: a crease of 0.5 instead of 1.5 is off by more than 1e-3', () => {
    const reference = opensubdiv({ fixture: 'tetra-crease.obj', scheme: 'loop' }, 1);
    const mesh = loadFixture('tetra-crease.obj');
    const tags = mesh.tags;
    if (!tags) throw new Error('tetra-crease.obj has tags');
    const other = subdivide(
      { ...mesh, tags: { ...tags, creaseSharpness: Float32Array.from([0.5]) } },
      { scheme: 'loop', levels: 1 },
    );
    const worst = Math.max(...Array.from(other.positions, (x, i) => Math.abs(x - reference.levels[0].positions[i])));
    expect(worst).toBeGreaterThan(1e-3);
  });
});
