#!/usr/bin/env node
// Launcher for the `subdiv` CLI: the code is bundled by `node scripts/setup.mjs`
// (vite.cli.config.ts) into build/cli/subdiv.mjs.
import { existsSync, realpathSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const root = join(dirname(realpathSync(fileURLToPath(import.meta.url))), '..');
const bundle = join(root, 'build', 'cli', 'subdiv.mjs');
if (!existsSync(bundle)) {
  process.stderr.write('error: the subdiv CLI is not built yet; run `node scripts/setup.mjs` first\n');
  process.exit(1);
}
const { main } = await import(pathToFileURL(bundle).href);
process.exitCode = await main(process.argv.slice(2));
