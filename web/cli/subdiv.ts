/**
 * The `subdiv` command: load an OFF/OBJ/PLY/STL mesh, subdivide it with the WASM core,
 * write it and/or print its facts. Bundled for Node into build/cli/subdiv.mjs
 * (vite.cli.config.ts) and started by bin/subdiv.mjs.
 */
import { closeSync, openSync, readFileSync, writeFileSync, writeSync } from 'node:fs';
import { basename } from 'node:path';
import { performance } from 'node:perf_hooks';
import { initNode } from '../core/init-node';
import type { Mesh, MeshFacts, MeshFormat, ReadFormat, ReadOptions, SchemeName, SubdivideOptions } from '../core/mesh';
import { parseRuleSetText, type RuleSet } from '../core/rule-set';
import { SCHEME_TABLE } from '../core/scheme-table';
import { fraction, vertexStencil } from '../core/stencils';
import {
  compareMeshes,
  formatFromFileName,
  halfedgeTable,
  hausdorffDistance,
  hostOf,
  inspectMesh,
  meshFacts,
  parseMesh,
  schemeNames,
  stepStencils,
  subdivide,
  subdivideForView,
  viewMesh,
  writeMesh,
} from '../core/subdiv-core';
import { SubdivError } from '../core/subdiv-error';
import { type CliArgs, parseCliArgs, USAGE, UsageError } from './cli-args';
import { renderFigure } from './figure-command';
import { halfedgeJson } from './halfedge-json';

/** Where the CLI writes; replaceable in tests. */
export interface CliIo {
  stdout: (text: string) => void;
  stderr: (text: string) => void;
}

const processIo: CliIo = {
  stdout: (text) => process.stdout.write(text),
  stderr: (text) => process.stderr.write(text),
};

/** Bad input: reported as one `error:` line, exit status 1. */
class InputError extends Error {}

/** OFF/OBJ/PLY/STL by extension; other names the core tells apart by their first bytes ('auto'). */
function inputFormat(path: string): ReadFormat {
  return formatFromFileName(path) ?? 'auto';
}

/** --repair-orientation as the core takes it. */
function readOptions(args: CliArgs): ReadOptions {
  return { repairOrientation: args.repairOrientation };
}

/** A mesh file's bytes (binary PLY and STL are not text). */
function readMeshFile(path: string): Uint8Array {
  return readFile(path);
}

function readInput(path: string): string {
  return new TextDecoder().decode(readFile(path));
}

function readFile(path: string): Uint8Array {
  try {
    return readFileSync(path);
  } catch (error) {
    const reason = (error as NodeJS.ErrnoException).code === 'ENOENT' ? 'no such file' : (error as Error).message;
    throw new InputError(`${path}: cannot read: ${reason}`);
  }
}

/** "file: line 7: message" from a core error (whose message may already start with "line 7: "). */
function locate(path: string, error: SubdivError): string {
  const prefix = `line ${error.line}: `;
  if (error.line > 0 && !error.message.startsWith(prefix)) return `${path}: ${prefix}${error.message}`;
  return `${path}: ${error.message}`;
}

/** The comment an output file carries: `SubdivLab: cube.off, Loop, level 2`. */
function outputComment(args: CliArgs): string {
  const label = SCHEME_TABLE.schemes.find((s) => s.name === args.scheme)?.label ?? args.scheme;
  return `SubdivLab: ${basename(args.input)}, ${label}, level ${args.levels}`;
}

/** Writes the mesh's file to `path` as the core produces it, without ever holding it whole. */
function writeMeshFile(path: string, mesh: Mesh, format: MeshFormat, comment: string): void {
  const fd = openSync(path, 'w');
  try {
    writeMesh(
      mesh,
      format,
      (chunk) => {
        for (let done = 0; done < chunk.length; ) done += writeSync(fd, chunk, done);
      },
      undefined,
      comment,
    );
  } finally {
    closeSync(fd);
  }
}

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

/** The rule set of --rule (null without), read and checked; a bad file is an InputError naming it. */
function readRules(args: CliArgs): RuleSet | undefined {
  if (args.rule === null) return undefined;
  const ruleText = readInput(args.rule);
  try {
    return parseRuleSetText(ruleText);
  } catch (error) {
    if (error instanceof SubdivError) throw new InputError(`${args.rule}: ${error.message}`);
    throw error;
  }
}

/** The core's options for the command line's scheme, levels and flags. */
function subdivideOptions(args: CliArgs, rules: RuleSet | undefined): SubdivideOptions {
  return {
    scheme: args.scheme as SchemeName,
    levels: args.levels,
    triangulate: args.triangulate,
    smoothBoundary: !args.fixedBoundary,
    ...(args.creaseMethod ? { creaseMethod: args.creaseMethod } : {}),
    ...(args.boundary ? { boundary: args.boundary } : {}),
    rules,
  };
}

/** A core error of a run: a rule value names the rule file, anything else the input. */
function inputError(args: CliArgs, error: unknown): unknown {
  if (!(error instanceof SubdivError)) return error;
  // Rule values are judged by the core: name the rule file, not the mesh.
  if (args.rule !== null && error.message.startsWith('custom rules:')) {
    return new InputError(`${args.rule}: ${error.message}`);
  }
  return new InputError(locate(args.input, error));
}

/**
 * `subdiv stencil`: vertex --vertex of level --level as the weighted sum of
 * level K - 1's vertices, with its kind, size and formula, as JSON.
 */
async function stencil(args: CliArgs, io: CliIo, rules: RuleSet | undefined): Promise<void> {
  const text = readMeshFile(args.input);
  try {
    const mesh = parseMesh(text, inputFormat(args.input), readOptions(args));
    const options = subdivideOptions(args, rules);
    const table = stepStencils(mesh, options);
    const count = table.kinds.length;
    if (args.vertex >= count) {
      throw new InputError(
        `${args.input}: level ${args.levels} has ${count} vertices (0 to ${count - 1}), so no vertex ${args.vertex}`,
      );
    }
    const s = vertexStencil(table, args.vertex);
    const position = Array.from(subdivide(mesh, options).positions.subarray(3 * s.vertex, 3 * s.vertex + 3));
    const size = /face|corner/.test(s.kind) ? { degree: s.size } : s.edge ? {} : { valence: s.size };
    const out = {
      scheme: args.scheme,
      level: args.levels,
      vertex: s.vertex,
      kind: s.kind,
      ...(s.edge ? { edge: s.edge } : s.element !== null ? { of: s.element } : {}),
      ...size,
      formula: s.formula,
      parents: s.parents.map(({ vertex, weight }) => {
        const exact = fraction(weight);
        return exact ? { vertex, weight, fraction: exact } : { vertex, weight };
      }),
      sum: s.parents.reduce((total, p) => total + p.weight, 0),
      position,
    };
    io.stdout(`${JSON.stringify(out, null, 2)}\n`);
  } catch (error) {
    throw inputError(args, error);
  }
}

/**
 * `subdiv inspect`: CGAL's geometry around the mesh or its level K, as
 * JSON (the hull's and pairs' arrays as counts and the first pairs).
 */
async function inspect(args: CliArgs, io: CliIo, rules: RuleSet | undefined): Promise<void> {
  const text = readMeshFile(args.input);
  let control: Mesh;
  let mesh: Mesh;
  try {
    control = parseMesh(text, inputFormat(args.input), readOptions(args));
    mesh = args.levels > 0 ? subdivide(control, subdivideOptions(args, rules)) : control;
  } catch (error) {
    throw inputError(args, error);
  }
  const i = inspectMesh(mesh, args.inspect);
  const pairs = i.selfIntersections;
  const out: Record<string, unknown> = {
    ...(args.levels > 0 ? { scheme: args.scheme, levels: args.levels } : {}),
    vertices: mesh.positions.length / 3,
    faces: mesh.faceSizes.length,
    measures: i.measures,
    ...(pairs
      ? {
          selfIntersections: {
            pairs: pairs.pairs,
            faces: pairs.faces.length,
            firstPairs: Array.from({ length: pairs.firstPairs.length / 2 }, (_, k) => [
              pairs.firstPairs[2 * k],
              pairs.firstPairs[2 * k + 1],
            ]),
            ms: pairs.ms,
          },
        }
      : {}),
    ...(i.sphere ? { sphere: i.sphere } : {}),
    ...(i.hull
      ? {
          hull: {
            vertices: i.hull.vertices,
            edges: i.hull.edges,
            faces: i.hull.faces,
            area: i.hull.area,
            volume: i.hull.volume,
            ms: i.hull.ms,
          },
        }
      : {}),
    ...(i.width ? { width: i.width } : {}),
  };
  if (args.levels > 0) {
    const before = inspectMesh(control).measures;
    out.control = before;
    const share = (a: number, b: number) => (b !== 0 ? a / b : null);
    out.change = {
      area: share(i.measures.area, before.area),
      volume: i.measures.closed && before.closed ? share(i.measures.volume, before.volume) : null,
      diagonal: share(i.measures.diagonal, before.diagonal),
    };
  }
  io.stdout(`${JSON.stringify(out, null, 2)}\n`);
}

/** Thrown by `subdiv check` on a mismatch, after its report: exit status 1 without an error line. */
class Mismatch extends Error {}

/**
 * `subdiv check CONTROL RESULT`: RESULT against the core's level of CONTROL,
 * as JSON; a mismatch ends with exit status 1.
 */
async function check(args: CliArgs, io: CliIo, rules: RuleSet | undefined): Promise<void> {
  const controlText = readMeshFile(args.input);
  const resultText = readMeshFile(args.result);
  let reference: Mesh;
  try {
    reference = subdivide(
      parseMesh(controlText, inputFormat(args.input), readOptions(args)),
      subdivideOptions(args, rules),
    );
  } catch (error) {
    throw inputError(args, error);
  }
  let result: Mesh;
  try {
    result = parseMesh(resultText, inputFormat(args.result), readOptions(args));
  } catch (error) {
    if (error instanceof SubdivError) throw new InputError(locate(args.result, error));
    throw error;
  }
  const c = compareMeshes(reference, result, args.tolerance);
  const at = (mesh: Mesh, v: number) => Array.from(mesh.positions.subarray(3 * v, 3 * v + 3));
  const report = {
    verdict: c.match ? 'match' : 'mismatch',
    scheme: args.scheme,
    levels: args.levels,
    reasons: c.reasons,
    reference: { vertices: c.referenceVertices, faces: c.referenceFaces },
    result: { vertices: c.resultVertices, faces: c.resultFaces },
    matching: c.matching,
    sameFaces: c.sameFaces,
    relativeTolerance: args.tolerance,
    tolerance: c.tolerance,
    maxError: c.maxError,
    meanError: c.meanError,
    worst: c.worst.map((w) => ({
      vertex: w.vertex,
      error: w.error,
      expected: at(reference, w.reference),
      got: at(result, w.vertex),
    })),
  };
  io.stdout(`${JSON.stringify(report, null, 2)}\n`);
  if (!c.match) throw new Mismatch();
}

/** `subdiv compare A B`: the symmetric Hausdorff distance between the two surfaces, as JSON. */
async function compare(args: CliArgs, io: CliIo): Promise<void> {
  await initNode();
  const meshes = [args.input, args.result].map((path) => {
    const text = readMeshFile(path);
    try {
      return parseMesh(text, inputFormat(path), readOptions(args));
    } catch (error) {
      if (error instanceof SubdivError) throw new InputError(locate(path, error));
      throw error;
    }
  });
  const h = hausdorffDistance(meshes[0], meshes[1]);
  const report = {
    distance: h.distance,
    relative: h.diagonal > 0 ? h.distance / h.diagonal : 0,
    diagonal: h.diagonal,
    errorBound: h.errorBound,
  };
  io.stdout(`${JSON.stringify(report, null, 2)}\n`);
}

/** `subdiv halfedges`: the halfedge table of the mesh or its level K, as JSON (halfedge-json.ts). */
async function halfedges(args: CliArgs, io: CliIo, rules: RuleSet | undefined): Promise<void> {
  const text = readMeshFile(args.input);
  try {
    const control = parseMesh(text, inputFormat(args.input), readOptions(args));
    const mesh = args.levels > 0 ? subdivide(control, subdivideOptions(args, rules)) : control;
    const header = {
      ...(args.levels > 0 ? { scheme: args.scheme, levels: args.levels } : {}),
      vertices: mesh.positions.length / 3,
      faces: mesh.faceSizes.length,
    };
    io.stdout(halfedgeJson(header, halfedgeTable(mesh)));
  } catch (error) {
    throw inputError(args, error);
  }
}

/** `subdiv figure`: the level as the app's vector figure (figure-command.ts), and what it shows as JSON. */
async function figure(args: CliArgs, io: CliIo, rules: RuleSet | undefined): Promise<void> {
  const options = args.figure;
  if (!options) return;
  const text = readMeshFile(args.input);
  let result: ReturnType<typeof renderFigure>;
  try {
    const control = viewMesh(parseMesh(text, inputFormat(args.input), readOptions(args)));
    const level =
      args.levels > 0 ? subdivideForView(control.mesh, subdivideOptions(args, rules), control.facts) : control;
    result = renderFigure(level, control, options, outputComment(args).replace(/^SubdivLab: /, ''));
  } catch (error) {
    throw inputError(args, error);
  }
  try {
    writeFileSync(options.path, result.contents);
  } catch (error) {
    throw new InputError(`${options.path}: cannot write: ${(error as Error).message}`);
  }
  const { path, format, width, height } = options;
  const report = { output: path, format, width, height, polygons: result.polygons, view: result.camera };
  io.stdout(`${JSON.stringify({ ...report, edgeOpacity: Math.round(result.edgeOpacity * 1000) / 1000 })}\n`);
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
