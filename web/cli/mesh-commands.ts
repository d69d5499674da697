/**
 * The `subdiv` commands that answer in JSON (and `figure`, which writes a
 * file): stencil, inspect, check, compare, halfedges, figure. Their shared
 * input handling is in cli-input.ts; subdiv.ts dispatches to them.
 */
import { writeFileSync } from 'node:fs';
import { initNode } from '../core/init-node';
import type { Mesh } from '../core/mesh';
import type { RuleSet } from '../core/rule-set';
import { fraction, vertexStencil } from '../core/stencils';
import {
  compareMeshes,
  halfedgeTable,
  hausdorffDistance,
  inspectMesh,
  parseMesh,
  stepStencils,
  subdivide,
  subdivideForView,
  viewMesh,
} from '../core/subdiv-core';
import { SubdivError } from '../core/subdiv-error';
import { vertexSources } from '../core/vertex-lines';
import type { CliArgs } from './cli-args';
import {
  type CliIo,
  InputError,
  inputError,
  inputFormat,
  locate,
  outputComment,
  readMeshFile,
  readOptions,
  subdivideOptions,
} from './cli-input';
import { renderFigure } from './figure-command';
import { halfedgeJson } from './halfedge-json';

/**
 * `subdiv stencil`: vertex --vertex of level --level as the weighted sum of
 * level K - 1's vertices, with its kind, size and formula, as JSON.
 */
export async function stencil(args: CliArgs, io: CliIo, rules: RuleSet | undefined): Promise<void> {
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
export async function inspect(args: CliArgs, io: CliIo, rules: RuleSet | undefined): Promise<void> {
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
export class Mismatch extends Error {}

/**
 * `subdiv check CONTROL RESULT`: RESULT against the core's level of CONTROL,
 * as JSON; a mismatch ends with exit status 1.
 */
export async function check(args: CliArgs, io: CliIo, rules: RuleSet | undefined): Promise<void> {
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
  // Where each worst vertex is in RESULT: its line, and in OBJ its 1-based "v" number (core/vertex-lines.ts).
  const sources = vertexSources(resultText, inputFormat(args.result));
  const inFile = (v: number) => {
    const s = sources?.vertices.length === result.positions.length / 3 ? sources.vertices[v] : undefined;
    if (!s) return {};
    return sources?.format === 'obj' ? { line: s.line, objVertex: s.fileVertex + 1 } : { line: s.line };
  };
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
      ...inFile(w.vertex),
      error: w.error,
      expected: at(reference, w.reference),
      got: at(result, w.vertex),
    })),
  };
  io.stdout(`${JSON.stringify(report, null, 2)}\n`);
  if (!c.match) throw new Mismatch();
}

/** `subdiv compare A B`: the symmetric Hausdorff distance between the two surfaces, as JSON. */
export async function compare(args: CliArgs, io: CliIo): Promise<void> {
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
export async function halfedges(args: CliArgs, io: CliIo, rules: RuleSet | undefined): Promise<void> {
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
export async function figure(args: CliArgs, io: CliIo, rules: RuleSet | undefined): Promise<void> {
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
