/**
 * The symmetric Hausdorff distance as the `subdiv` CLI gives it: each
 * scheme's level written by `subdiv -o`, then `subdiv compare` — what the
 * side-by-side tests check the app's and the element's figures against.
 */
import { spawnSync } from 'node:child_process';
import { mkdtempSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { expect } from '@playwright/test';

/** Runs the `subdiv` CLI; its standard output. */
function subdiv(args: string[]): string {
  const r = spawnSync(process.execPath, ['bin/subdiv.mjs', ...args], { encoding: 'utf8' });
  expect(r.stderr).toBe('');
  expect(r.status).toBe(0);
  return r.stdout;
}

export interface CliDistance {
  distance: number;
  relative: number;
  diagonal: number;
  errorBound: number;
}

/** `subdiv compare` of `mesh`'s level `a[1]` under scheme `a[0]` and level `b[1]` under `b[0]` (triangulated first). */
export function cliDistance(mesh: string, a: [string, number], b: [string, number]): CliDistance {
  const work = mkdtempSync(join(tmpdir(), 'side-by-side-'));
  const files = [a, b].map(([scheme, levels], i) => {
    const file = join(work, `${i}-${scheme}.off`);
    subdiv([mesh, '--scheme', scheme, '--triangulate', '--levels', String(levels), '-o', file]);
    return file;
  });
  return JSON.parse(subdiv(['compare', ...files]));
}
