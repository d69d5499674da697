/**
 * The `subdiv` command: load an OFF/OBJ/PLY/STL mesh, subdivide it with the WASM core,
 * write it and/or print its facts; `info` here, the other commands in
 * mesh-commands.ts. Bundled for Node into build/cli/subdiv.mjs
 * (vite.cli.config.ts) and started by bin/subdiv.mjs.
 */
import { performance } from 'node:perf_hooks';
import { initNode } from '../core/init-node';
import type { Mesh, MeshFacts } from '../core/mesh';
import { hostOf, meshFacts, parseMesh, schemeNames, subdivide, writeMesh } from '../core/subdiv-core';
import { SubdivError } from '../core/subdiv-error';
import { type CliArgs, parseCliArgs, USAGE, UsageError } from './cli-args';
import {
  type CliIo,
  InputError,
  inputError,
  inputFormat,
  locate,
  outputComment,
  processIo,
  readMeshFile,
  readOptions,
  readRules,
  subdivideOptions,
  writeMeshFile,
} from './cli-input';
import { check, compare, figure, halfedges, inspect, Mismatch, stencil } from './mesh-commands';

export type { CliIo } from './cli-input';

/**
 * What `subdiv info` prints: the facts of the loaded mesh, then its tags
 * (counts, border mode, crease method; "(from the file)" where a tag set
 * them) and the notes on tags the core read but does not apply.
 */
export function infoText(mesh: Mesh, facts: MeshFacts): string {
  const tags = mesh.tags;
  const lines = [
    `vertices: ${facts.vertices}`,
    `edges: ${facts.edges}`,
    `faces: ${facts.faces} (${facts.triangles} triangles, ${facts.quads} quads, ${facts.otherFaces} other)`,
    `components: ${facts.components}`,
    `boundaries: ${facts.boundaries}`,
    `genus: ${facts.genus}`,
    `closed: ${facts.closed ? 'yes' : 'no'}`,
    `creases: ${tags ? tags.creaseSharpness.length : 0}`,
    `corners: ${tags ? tags.cornerSharpness.length : 0}`,
    `holes: ${tags ? tags.holes.length : 0}`,
    `boundary: ${tags?.boundary ?? 'edge'}${tags?.boundaryGiven ? ' (from the file)' : ''}`,
    `crease method: ${tags?.creaseMethod ?? 'uniform'}${tags?.creaseMethodGiven ? ' (from the file)' : ''}`,
    ...(tags?.notes ?? []).map((note) => `note: ${note}`),
  ];
  return `${lines.join('\n')}\n`;
}

async function info(args: CliArgs, io: CliIo): Promise<void> {
  await initNode();
  const text = readMeshFile(args.input);
  try {
    const mesh = parseMesh(text, inputFormat(args.input), readOptions(args));
    io.stdout(infoText(mesh, meshFacts(mesh)));
  } catch (error) {
    if (error instanceof SubdivError) throw new InputError(locate(args.input, error));
    throw error;
  }
}

async function run(args: CliArgs, io: CliIo): Promise<void> {
  if (args.command === 'info') return info(args, io);
  if (args.command === 'compare') return compare(args, io);
  await initNode();
  const schemes = schemeNames();
  if (!schemes.includes(args.scheme)) {
    throw new UsageError(`unknown scheme "${args.scheme}" (known: ${schemes.join(', ')})`);
  }
  const rules = readRules(args);
  if (args.command === 'stencil') return stencil(args, io, rules);
  if (args.command === 'check') return check(args, io, rules);
  if (args.command === 'inspect') return inspect(args, io, rules);
  if (args.command === 'halfedges') return halfedges(args, io, rules);
  if (args.command === 'figure') return figure(args, io, rules);
  const text = readMeshFile(args.input);
  let result: Mesh;
  let ms: number;
  try {
    const mesh = parseMesh(text, inputFormat(args.input), readOptions(args));
    const start = performance.now();
    result = subdivide(mesh, subdivideOptions(args, rules));
    ms = performance.now() - start;
  } catch (error) {
    throw inputError(args, error);
  }
  if (args.output) {
    try {
      writeMeshFile(args.output.path, result, args.output.format, outputComment(args));
    } catch (error) {
      if (error instanceof SubdivError) throw new InputError(locate(args.output.path, error));
      throw new InputError(`${args.output.path}: cannot write: ${(error as Error).message}`);
    }
  }
  if (args.stats) {
    const f = meshFacts(result);
    const stats: Record<string, number | boolean> = {
      vertices: f.vertices,
      edges: f.edges,
      faces: f.faces,
      components: f.components,
      boundaries: f.boundaries,
      eulerCharacteristic: f.eulerCharacteristic,
      genus: f.genus,
      closed: f.closed,
      triangles: f.triangles,
      quads: f.quads,
      otherFaces: f.otherFaces,
    };
    // Primal schemes carry the control mesh's edges (0 levels: all of them).
    if (result.controlEdges.length > 0 || hostOf(args.scheme, rules)?.keepsControlEdges)
      stats.controlEdges = f.controlEdges;
    stats.ms = Math.round(ms * 1000) / 1000;
    io.stdout(`${JSON.stringify(stats)}\n`);
  }
  if (!args.output && !args.stats) {
    // Piece by piece: a text beyond one string's 512 M characters prints too.
    const decoder = new TextDecoder();
    writeMesh(result, 'off', (chunk) => io.stdout(decoder.decode(chunk)));
  }
}

/**
 * Runs the CLI on `argv` (without node and the script) and returns the exit
 * status: 0 success, 1 bad input (one `error:` line on stderr), 2 bad usage.
 */
export async function main(argv: string[], io: CliIo = processIo): Promise<number> {
  try {
    const args = parseCliArgs(argv);
    if (args.help) {
      io.stdout(`${USAGE}\n`);
      return 0;
    }
    await run(args, io);
    return 0;
  } catch (error) {
    if (error instanceof UsageError) {
      io.stderr(`subdiv: ${error.message}\n${USAGE}\n`);
      return 2;
    }
    if (error instanceof InputError) {
      io.stderr(`error: ${error.message}\n`);
      return 1;
    }
    if (error instanceof Mismatch) return 1;
    const message = error instanceof Error ? error.message : String(error);
    io.stderr(`error: ${message.split('\n')[0]}\n`);
    return 1;
  }
}
