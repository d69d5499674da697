/**
 * Properties of subdiv's command line (web/cli/cli-args.ts), with
 * fast-check: any argv is parsed or refused with a UsageError (exit status
 * 2) whose message names the problem; a command line made of valid options,
 * in any order, is read as the options it gives.
 */
import fc from 'fast-check';
import './seed';
import { describe, expect, it } from 'vitest';
import { type CliArgs, DEFAULT_TOLERANCE, parseCliArgs, UsageError } from '../../../web/cli/cli-args';

const OPTIONS = [
  '--scheme',
  '--levels',
  '--level',
  '--vertex',
  '--tolerance',
  '--triangulate',
  '--rule',
  '--fixed-boundary',
  '--crease-method',
  '--boundary',
  '--output',
  '-o',
  '--stats',
  '--repair-orientation',
  '--self-intersections',
  '--sphere',
  '--hull',
  '--width',
  '--all',
  '--view',
  '--mode',
  '--control-mesh',
  '--curves',
  '--size',
  '--line-width',
  '--transparent',
  '--help',
  '-h',
];
const WORDS = ['info', 'stencil', 'check', 'compare', 'inspect', 'halfedges', 'figure', 'in.off', 'out.obj', 'f.svg'];
const VALUES = [
  '0',
  '1',
  '3',
  '-1',
  '1e-3',
  '',
  ' ',
  'x',
  'loop',
  'custom',
  'uniform',
  'none',
  '800x600',
  'iso',
  '2',
  '0x10',
];

/** Parses `argv`: the arguments, or the UsageError (anything else thrown fails the property). */
function parse(argv: string[]): CliArgs | UsageError {
  try {
    return parseCliArgs(argv);
  } catch (error) {
    if (!(error instanceof UsageError)) throw error;
    return error;
  }
}

describe('subdiv command lines: any argv', () => {
  it('is parsed or refused with a UsageError that names the problem', () => {
    const arg = fc.oneof(
      fc.constantFrom(...OPTIONS, ...WORDS, ...VALUES),
      fc.constantFrom(...OPTIONS).map((o) => `${o}=`),
      fc.string({ unit: 'binary', maxLength: 10 }),
    );
    fc.assert(
      fc.property(fc.array(arg, { maxLength: 10 }), (argv) => {
        const r = parse(argv);
        if (r instanceof UsageError) {
          expect(r.message).toMatch(/\S/);
          expect(r.name).toBe('UsageError');
          return;
        }
        expect(['subdivide', 'info', 'stencil', 'check', 'compare', 'inspect', 'halfedges', 'figure']).toContain(
          r.command,
        );
        expect(Number.isInteger(r.levels) && r.levels >= 0).toBe(true);
        expect(r.tolerance >= 0 && Number.isFinite(r.tolerance)).toBe(true);
      }),
      // node:util's parseArgs takes about a millisecond a call: 200 runs.
      { numRuns: 200 },
    );
  });

  it('a --tolerance that is not a decimal number is refused, not read as 0 or as hex (shrunk counterexamples "", " ")', () => {
    fc.assert(
      fc.property(
        fc.oneof(fc.string({ maxLength: 8 }), fc.constantFrom('', ' ', '0x10', '0b1', 'Infinity', '1e999')),
        (text) => {
          // With '=': parseArgs takes any text, "-x" too, as the option's value.
          const r = parse(['check', 'a.off', 'b.off', `--tolerance=${text}`]);
          const decimal = /^\s*[+]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?\s*$/.test(text) && Number.isFinite(Number(text));
          if (decimal) {
            expect(r).not.toBeInstanceOf(UsageError);
            if (!(r instanceof UsageError)) expect(r.tolerance).toBe(Number(text));
          } else {
            expect(r).toBeInstanceOf(UsageError);
            if (r instanceof UsageError)
              expect(r.message).toBe(`--tolerance must be a number 0 or more, not "${text}"`);
          }
        },
      ),
      { numRuns: 300 },
    );
    for (const bad of ['', ' ', '0x10']) {
      expect(() => parseCliArgs(['check', 'a.off', 'b.off', '--tolerance', bad])).toThrow(
        `--tolerance must be a number 0 or more, not "${bad}"`,
      );
    }
  });
});

describe('subdiv command lines: valid ones', () => {
  it('subdividing: the options given, in any order, are the options read', () => {
    const schemes = ['catmull-clark', 'loop', 'doo-sabin', 'sqrt3', 'quad-triangle', 'linear', 'linear-tri'];
    fc.assert(
      fc.property(
        fc.record({
          input: fc.constantFrom('in.off', 'a b.obj', 'mesh.ply', 'x.stl'),
          scheme: fc.option(fc.constantFrom(...schemes), { nil: undefined }),
          levels: fc.option(fc.nat(12), { nil: undefined }),
          triangulate: fc.boolean(),
          fixedBoundary: fc.boolean(),
          creaseMethod: fc.option(fc.constantFrom('uniform', 'chaikin'), { nil: undefined }),
          boundary: fc.option(fc.constantFrom('edge', 'edge-and-corner', 'none'), { nil: undefined }),
          output: fc.option(fc.constantFrom('out.off', 'OUT.OBJ', 'r.ply', 'r.stl'), { nil: undefined }),
          stats: fc.boolean(),
          repair: fc.boolean(),
          equals: fc.boolean(),
        }),
        fc.infiniteStream(fc.nat()),
        (o, order) => {
          const groups: string[][] = [];
          const value = (name: string, v: string) => groups.push(o.equals ? [`${name}=${v}`] : [name, v]);
          if (o.scheme !== undefined) value('--scheme', o.scheme);
          if (o.levels !== undefined) value('--levels', String(o.levels));
          if (o.triangulate) groups.push(['--triangulate']);
          if (o.fixedBoundary) groups.push(['--fixed-boundary']);
          if (o.creaseMethod !== undefined) value('--crease-method', o.creaseMethod);
          if (o.boundary !== undefined) value('--boundary', o.boundary);
          if (o.output !== undefined) value('--output', o.output);
          if (o.stats) groups.push(['--stats']);
          if (o.repair) groups.push(['--repair-orientation']);
          groups.splice(order.next().value % (groups.length + 1), 0, [o.input]);
          // Shuffle the option groups (the input stays where it was put).
          const argv = groups
            .map((g, i) => ({ g, key: g[0] === o.input ? i : order.next().value }))
            .sort((a, b) => a.key - b.key)
            .flatMap(({ g }) => g);
          const r = parseCliArgs(argv);
          expect(r).toMatchObject({
            command: 'subdivide',
            input: o.input,
            scheme: o.scheme ?? 'catmull-clark',
            levels: o.levels ?? 1,
            triangulate: o.triangulate,
            fixedBoundary: o.fixedBoundary,
            creaseMethod: o.creaseMethod ?? null,
            boundary: o.boundary ?? null,
            output: o.output === undefined ? null : { path: o.output, format: o.output.slice(-3).toLowerCase() },
            stats: o.stats,
            repairOrientation: o.repair,
            tolerance: DEFAULT_TOLERANCE,
            help: false,
          });
        },
      ),
      { numRuns: 500 },
    );
  });

  it('figure: size, line width, mode and view are read as given', () => {
    fc.assert(
      fc.property(
        fc.integer({ min: 16, max: 20000 }),
        fc.integer({ min: 16, max: 20000 }),
        fc.double({ min: 0.25, max: 8, noNaN: true }),
        fc.constantFrom('edges', 'flat', 'smooth', 'wireframe'),
        fc.constantFrom('front', 'top', 'side', 'iso'),
        (w, h, lineWidth, mode, view) => {
          const r = parseCliArgs([
            'figure',
            'in.off',
            '--size',
            `${w}x${h}`,
            '--line-width',
            String(lineWidth),
            '--mode',
            mode,
            '--view',
            view,
            '-o',
            'f.pdf',
          ]);
          expect(r.figure).toMatchObject({ path: 'f.pdf', format: 'pdf', width: w, height: h, lineWidth, mode, view });
        },
      ),
      { numRuns: 200 },
    );
  });
});
