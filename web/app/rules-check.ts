/**
 * The core's judgement of a custom rule set without a model: the core checks
 * the rules (check_custom_rules: every weight finite, every stencil summing
 * to 1, naming the rule and the valence) before anything else when it
 * predicts a step, so a prediction on a tetrahedron asks exactly that.
 * The rules panel shows that message; there is no second validator in the UI.
 */
import type { Mesh } from '../core/mesh';
import type { RuleSet } from '../core/rule-set';
import { CancelledError, type WorkerClient } from '../core/worker-client';

/** A regular tetrahedron: triangles, so every host (PTQ and √3 included) takes it. */
function tetrahedron(): Mesh {
  return {
    positions: new Float64Array([1, 1, 1, 1, -1, -1, -1, 1, -1, -1, -1, 1]),
    faceSizes: new Uint32Array([3, 3, 3, 3]),
    faceIndices: new Uint32Array([0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2]),
    controlEdges: new Uint32Array(0),
  };
}

/** Resolves when the core accepts `rules`; rejects with its SubdivError (code invalid_argument) otherwise. */
export async function checkRulesInCore(client: WorkerClient, rules: RuleSet): Promise<void> {
  const options = { scheme: 'custom' as const, levels: 1, rules };
  try {
    await client.predictSize(tetrahedron(), options);
  } catch (error) {
    // A cancelled step restarts the worker and takes queued requests with it: ask again.
    if (!(error instanceof CancelledError)) throw error;
    await client.predictSize(tetrahedron(), options);
  }
}
