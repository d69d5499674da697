/** The CLI on every file of tests/fixtures/invalid: exit 1 and one `error:` line naming the file and the line. */
import { spawnSync } from 'node:child_process';
import { readdirSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { beforeAll, describe, expect, it } from 'vitest';
import { initNode } from '../../web/core/init-node';
import { formatFromFileName, parseMesh } from '../../web/core/subdiv-core';
import { SubdivError } from '../../web/core/subdiv-error';
import { FIXTURES_DIR, fixtureText } from './test-helpers';

const BIN = join(dirname(fileURLToPath(import.meta.url)), '..', '..', 'bin', 'subdiv.mjs');
const INVALID = join(FIXTURES_DIR, 'invalid');
const files = readdirSync(INVALID).filter((name) => formatFromFileName(name) !== null);

beforeAll(async () => {
  await initNode();
});

describe('subdiv on invalid files', () => {
  it('has files to check', () => {
    expect(files.length).toBeGreaterThanOrEqual(10);
  });

  it.each(files)('%s', (name) => {
    // What the API says about the file: the CLI must say the same, naming the file.
    let error: SubdivError | null = null;
    try {
      parseMesh(fixtureText(join('invalid', name)), formatFromFileName(name) ?? 'off');
    } catch (e) {
      error = e as SubdivError;
    }
    expect(error).toBeInstanceOf(SubdivError);
    const core = error as SubdivError;

    const r = spawnSync(process.execPath, [BIN, name, '--stats'], { cwd: INVALID, encoding: 'utf8' });
    expect(r.status).toBe(1);
    expect(r.stdout).toBe('');
    const lines = r.stderr.split('\n');
    expect(lines).toHaveLength(2);
    expect(lines[1]).toBe('');
    expect(lines[0].startsWith(`error: ${name}: `)).toBe(true);
    expect(lines[0]).toContain(core.message.replace(/^line \d+: /, ''));
    if (core.line > 0) expect(lines[0]).toContain(`${name}: line ${core.line}: `);
    else expect(lines[0]).not.toMatch(/line \d+:/);
  });
});
