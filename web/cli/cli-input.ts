/**
 * What the `subdiv` commands share: where they write, reading the input
 * mesh and rule file, the core's options from the command line, writing a
 * mesh file, and bad input turned into one `error:` line (InputError).
 */
import { closeSync, openSync, readFileSync, writeSync } from 'node:fs';
import { basename } from 'node:path';
import type { Mesh, MeshFormat, ReadFormat, ReadOptions, SchemeName, SubdivideOptions } from '../core/mesh';
import { parseRuleSetText, type RuleSet } from '../core/rule-set';
import { SCHEME_TABLE } from '../core/scheme-table';
import { formatFromFileName, writeMesh } from '../core/subdiv-core';
import { SubdivError } from '../core/subdiv-error';
import type { CliArgs } from './cli-args';

/** Where the CLI writes; replaceable in tests. */
export interface CliIo {
  stdout: (text: string) => void;
  stderr: (text: string) => void;
}

export const processIo: CliIo = {
  stdout: (text) => process.stdout.write(text),
  stderr: (text) => process.stderr.write(text),
};

/** Bad input: reported as one `error:` line, exit status 1. */
export class InputError extends Error {}

/** OFF/OBJ/PLY/STL by extension; other names the core tells apart by their first bytes ('auto'). */
export function inputFormat(path: string): ReadFormat {
  return formatFromFileName(path) ?? 'auto';
}

/** --repair-orientation as the core takes it. */
export function readOptions(args: CliArgs): ReadOptions {
  return { repairOrientation: args.repairOrientation };
}

/** A mesh file's bytes (binary PLY and STL are not text). */
export function readMeshFile(path: string): Uint8Array {
  return readFile(path);
}

export function readInput(path: string): string {
  return new TextDecoder().decode(readFile(path));
}

export function readFile(path: string): Uint8Array {
  try {
    return readFileSync(path);
  } catch (error) {
    const reason = (error as NodeJS.ErrnoException).code === 'ENOENT' ? 'no such file' : (error as Error).message;
    throw new InputError(`${path}: cannot read: ${reason}`);
  }
}

/**
 * "file: line 7: message" from a core error, whose message may already name
 * the line ("line 7: ..." or, for an OBJ statement continued over lines,
 * "line 7 (continued to line 9): ...").
 */
export function locate(path: string, error: SubdivError): string {
  const named = new RegExp(`^line ${error.line}\\b`).test(error.message);
  if (error.line > 0 && !named) return `${path}: line ${error.line}: ${error.message}`;
  return `${path}: ${error.message}`;
}

/** The comment an output file carries: `SubdivLab: cube.off, Loop, level 2`. */
export function outputComment(args: CliArgs): string {
  const label = SCHEME_TABLE.schemes.find((s) => s.name === args.scheme)?.label ?? args.scheme;
  return `SubdivLab: ${basename(args.input)}, ${label}, level ${args.levels}`;
}

/** Writes the mesh's file to `path` as the core produces it, without ever holding it whole. */
export function writeMeshFile(path: string, mesh: Mesh, format: MeshFormat, comment: string): void {
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

/** The rule set of --rule (null without), read and checked; a bad file is an InputError naming it. */
export function readRules(args: CliArgs): RuleSet | undefined {
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
export function subdivideOptions(args: CliArgs, rules: RuleSet | undefined): SubdivideOptions {
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
export function inputError(args: CliArgs, error: unknown): unknown {
  if (!(error instanceof SubdivError)) return error;
  // Rule values are judged by the core: name the rule file, not the mesh.
  if (args.rule !== null && error.message.startsWith('custom rules:')) {
    return new InputError(`${args.rule}: ${error.message}`);
  }
  return new InputError(locate(args.input, error));
}
