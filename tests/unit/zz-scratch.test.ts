import { test } from 'vitest';
import type { Mesh } from '../../web/core/mesh';
import { subdivide, subdivideForView, meshFacts } from '../../web/core/subdiv-core';
import { initNode } from '../../web/core/init-node';

function grid(n: number): Mesh {
  const positions = new Float64Array(3 * (n + 1) * (n + 1));
  for (let j = 0; j <= n; j++) for (let i = 0; i <= n; i++) { const v = j * (n + 1) + i; positions[3 * v] = i; positions[3 * v + 1] = j; positions[3 * v + 2] = Math.sin(i * 0.1) * Math.cos(j * 0.1); }
  const faceSizes = new Uint32Array(n * n).fill(4);
  const faceIndices = new Uint32Array(4 * n * n);
  for (let j = 0, f = 0; j < n; j++) for (let i = 0; i < n; i++, f++) { const a = j * (n + 1) + i; faceIndices.set([a, a + 1, a + n + 2, a + n + 1], 4 * f); }
  return { positions, faceSizes, faceIndices, controlEdges: new Uint32Array(0) } as unknown as Mesh;
}
test('time', async () => {
  await initNode();
  const base = subdivide(grid(1000), { scheme: 'catmull-clark', levels: 1 });
  const facts = meshFacts(base);
  for (let r = 0; r < 2; r++) {
    let t = performance.now();
    const m = subdivide(base, { scheme: 'catmull-clark', levels: 1 });
    const a = performance.now() - t;
    t = performance.now();
    const v = subdivideForView(base, { scheme: 'catmull-clark', levels: 1 }, facts);
    const b = performance.now() - t;
    console.log(`subdivide ${a.toFixed(0)} ms, forView ${b.toFixed(0)} ms, faces ${v.facts.faces} ${m.faceSizes.length}`);
  }
}, 600000);
