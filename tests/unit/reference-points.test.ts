/** √3 and Doo-Sabin through the WASM core against plain implementations of the published rules (closed meshes). */
import { beforeAll, describe, it } from 'vitest';
import { initNode } from '../../web/core/init-node';
import { subdivide } from '../../web/core/subdiv-core';
import { dooSabinPoints, repeat, sqrt3ClosedStep } from './reference-subdivision';
import { expectSameMesh, loadFixture, matchPoints, toPlain } from './test-helpers';

beforeAll(async () => {
  await initNode();
});

describe('√3 point by point and face by face', () => {
  it.each(['tetrahedron.off', 'octahedron.off', 'icosahedron.off', 'torus-tri.off'])('%s, levels 1-3', (fixture) => {
    const mesh = loadFixture(fixture);
    for (let levels = 1; levels <= 3; levels++) {
      expectSameMesh(subdivide(mesh, { scheme: 'sqrt3', levels }), repeat(sqrt3ClosedStep, toPlain(mesh), levels));
    }
  });
});

describe('Doo-Sabin points', () => {
  it.each(['cube.off', 'tetrahedron.off', 'icosahedron.off', 'torus-quad.off', 'rhombicuboctahedron.off'])(
    '%s, level 1: one point per face corner by the Doo-Sabin weights',
    (fixture) => {
      const mesh = loadFixture(fixture);
      const out = toPlain(subdivide(mesh, { scheme: 'doo-sabin', levels: 1 }));
      matchPoints(out.points, dooSabinPoints(toPlain(mesh)));
    },
  );

  it('level 2 of the cube: the points of the level-1 faces', () => {
    const cube = loadFixture('cube.off');
    const level1 = toPlain(subdivide(cube, { scheme: 'doo-sabin', levels: 1 }));
    const level2 = toPlain(subdivide(cube, { scheme: 'doo-sabin', levels: 2 }));
    matchPoints(level2.points, dooSabinPoints(level1));
  });
});
