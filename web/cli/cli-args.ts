import { parseArgs } from 'node:util';
import type { BoundaryInterpolation, CreaseMethod, MeshFormat } from '../core/mesh';
import type { FigureFormat } from '../render/figure';
import { DEFAULT_LINE_WIDTH, MAX_LINE_WIDTH, MIN_LINE_WIDTH, parseLineWidth } from '../render/line-style';
import { FIGURE_MODES, type FigureMode, type FigureOptions, parseFigureView } from './figure-command';

/** The usage text printed by --help and on bad usage. */
export const USAGE = `usage: subdiv INPUT [--scheme S] [--levels N] [--triangulate] [-o OUTPUT.off|.obj|.ply|.stl] [--stats]
              [--rule RULES.json] [--fixed-boundary] [--crease-method M] [--boundary B]
              [--repair-orientation]
       subdiv info INPUT [--repair-orientation]
       subdiv stencil INPUT --level K --vertex I [--scheme S] [--triangulate] [--rule RULES.json] ...
       subdiv check CONTROL RESULT [--scheme S] [--levels K] [--tolerance T] [--triangulate] ...
       subdiv compare A B
       subdiv inspect INPUT [--self-intersections] [--sphere] [--hull] [--width] [--all]
                     [--scheme S --levels K] ...
       subdiv halfedges INPUT [--scheme S --levels K] ...
       subdiv figure INPUT [--scheme S --levels K] [--view V] [--mode M] [--control-mesh] [--curves]
                    [--size WxH] [--line-width W] [--transparent] -o OUT.svg|.pdf|.eps

  INPUT            an OFF, OBJ, PLY or STL mesh (format from the extension; otherwise from the
                   content; ASCII and binary PLY and STL, STL corners welded by exact position)
  --scheme S       catmull-clark (default), loop, doo-sabin, sqrt3, quad-triangle, linear,
                   linear-tri or custom
  --levels N       number of subdivision steps, 0 or more (default 1; 0 = load, check, convert)
  --triangulate    triangulate first when the scheme needs triangles (loop, sqrt3, linear-tri,
                   custom on the ptq or sqrt3 host)
  --rule F         the rule set of --scheme custom, a JSON file (see public/rules/); implies
                   --scheme custom
  --fixed-boundary quad-triangle: keep border vertices on the control border polygon
  --crease-method M  uniform or chaikin: how semi-sharp creases decay (overrides the file's
                   t creasemethod tag)
  --boundary B     edge, edge-and-corner or none: how a tagged mesh's border is subdivided
                   (overrides the file's t interpolateboundary tag)
  -o, --output F   write the result to F, as OFF, OBJ, PLY (ASCII) or STL (binary, polygons
                   as triangle fans) by its extension, with a comment naming input, scheme
                   and level
  --repair-orientation  turn faces that disagree with their neighbours (CGAL's polygon-soup
                   orientation) instead of refusing the mesh; a non-orientable one is still
                   refused
  --stats          print the result's facts and the subdivision time as one JSON object
                   (with controlEdges, the marked control-mesh edges, for primal schemes)
  -h, --help       show this text

subdiv info INPUT prints the mesh's facts and its OpenSubdiv tags (creases, corners, holes,
border mode, crease method) with the notes on tags it does not apply.

subdiv stencil INPUT --level K --vertex I prints, as JSON, how vertex I of level K (numbered
as "subdiv INPUT --levels K -o OUT" numbers it) is made from the vertices of level K - 1 (as
"--levels K-1" numbers them; the input's own order for K = 1): its kind, the valence or face
degree, the scheme's formula, and each parent with its weight (as a fraction where exact).
It takes the subdividing options above but -o, --stats and --levels.

subdiv check CONTROL RESULT says whether RESULT (yours, from any program) is level K of
CONTROL under the scheme: same counts, the same faces, every vertex within --tolerance T
(a share of the bounding-box diagonal, default 1e-6). Vertices are matched in order where
that fits, else each to the nearest reference vertex. It prints the verdict, the reasons,
the largest and mean errors and the worst vertices (by their number in RESULT, with their
line in OFF and OBJ and their "v" number in OBJ) as JSON, and
exits 0 on a match, 1 on a mismatch. It takes the subdividing options but -o and --stats.

subdiv compare A B prints the symmetric Hausdorff distance between the two surfaces as
JSON: distance, relative (to the bounding-box diagonal of both), diagonal and errorBound
(the distance is within it of the true one: 1e-4 of the diagonal).

subdiv inspect INPUT prints, as JSON, CGAL's geometry around the mesh (or around its level K
of --scheme S, with --levels K; default 0, the mesh as given): area, volume (closed meshes)
and bounding box, and as asked (all of them without a choice, or with --all) the
self-intersecting face pairs (exact predicates), the smallest enclosing sphere, the convex
hull and the minimum width with its planes, each with the milliseconds it took. With
--levels K, also the input's measures and the level's as shares of them.

subdiv halfedges INPUT prints, as JSON, the halfedge table of the mesh (or of its level K
of --scheme S, with --levels K; default 0) as CGAL's Surface_mesh numbers it: for each
halfedge h its next, prev and opposite halfedge (h xor 1), the vertex it points to and the
face it bounds (null on the border), one halfedge per line; vertices and faces in the
file's order (level K's as "subdiv INPUT --levels K -o OUT" writes them).

subdiv figure INPUT -o OUT draws the mesh (or its level K of --scheme S) as the app's Export
menu does, a vector figure by the extension: SVG, PDF (pdfLaTeX) or EPS (latex + dvips;
opaque, fading lines mixed with what lies under them). --view front, top, side or iso (the
app's canonical views, framed by its Fit), or a camera as the app's links write it
("px,py,pz,tx,ty,tz,ux,uy,uz"); default the app's first view. --mode edges (default: shaded
polygons with their edges), flat (no edges; smooth is the same), wireframe (every edge, no
faces). --control-mesh draws the cage, --curves the control-edge curves (primal schemes); a
tagged file's creases and corners are drawn as the app shows them. --size WxH in pixels, a
point each in PDF and EPS (default 800x600); --line-width W the app's line width (default 1);
--transparent leaves out the background. It prints the output file, the polygons drawn and
the camera as JSON.

Without -o and --stats the result is written to stdout as OFF.
Exit status: 0 success, 1 bad input (one "error:" line on stderr), 2 bad usage.`;

/** A command line that made sense. */
export interface CliArgs {
  /** `subdiv info|stencil|check|compare|inspect|halfedges ...`, or the default, subdividing. */
  command: 'subdivide' | 'info' | 'stencil' | 'check' | 'compare' | 'inspect' | 'halfedges' | 'figure';
  input: string;
  scheme: string;
  levels: number;
  triangulate: boolean;
  /** --rule: path of a rule file (scheme custom). */
  rule: string | null;
  /** --fixed-boundary. */
  fixedBoundary: boolean;
  /** --crease-method, or null for the mesh's own. */
  creaseMethod: CreaseMethod | null;
  /** --boundary, or null for the mesh's own. */
  boundary: BoundaryInterpolation | null;
  output: { path: string; format: MeshFormat } | null;
  stats: boolean;
  /** stencil: --vertex (levels holds --level). */
  vertex: number;
  /** check: the result to check (input is the control mesh), and --tolerance. */
  result: string;
  tolerance: number;
  /** --repair-orientation: faces turned to agree when they only disagree. */
  repairOrientation: boolean;
  /** inspect: what to compute besides the measures. */
  inspect: { selfIntersections: boolean; sphere: boolean; hull: boolean; width: boolean };
  /** figure: the output file and how to draw it. */
  figure: (FigureOptions & { path: string }) | null;
  help: boolean;
}

/** Thrown for bad usage: the CLI prints the message and the usage, exit status 2. */
export class UsageError extends Error {
  constructor(message: string) {
    super(message);
    this.name = 'UsageError';
  }
}

function outputFormat(path: string): MeshFormat {
  const match = /\.(off|obj|ply|stl)$/i.exec(path);
  if (!match) throw new UsageError(`output file ${path} must end in .off, .obj, .ply or .stl`);
  return match[1].toLowerCase() as MeshFormat;
}

/** subdiv check's tolerance: a share of the reference's bounding-box diagonal. */
export const DEFAULT_TOLERANCE = 1e-6;

/** The options of a command line that gives none (help, info). */
const NO_OPTIONS = {
  levels: 0,
  triangulate: false,
  rule: null,
  fixedBoundary: false,
  creaseMethod: null,
  boundary: null,
  output: null,
  stats: false,
  vertex: 0,
  result: '',
  tolerance: DEFAULT_TOLERANCE,
  inspect: { selfIntersections: false, sphere: false, hull: false, width: false },
  repairOrientation: false,
  figure: null,
} as const satisfies Partial<CliArgs>;

/** Parses argv (without node and the script). Throws UsageError; scheme names are checked later. */
export function parseCliArgs(argv: string[]): CliArgs {
  let parsed: ReturnType<typeof parse>;
  try {
    parsed = parse(argv);
  } catch (error) {
    throw new UsageError(error instanceof Error ? error.message : String(error));
  }
  const { values, positionals } = parsed;
  const help = values.help === true;
  if (help) return { ...NO_OPTIONS, command: 'subdivide', input: '', scheme: '', help };
  if (positionals[0] === 'info') return infoArgs(parsed);
  if (positionals[0] === 'compare') return compareArgs(parsed);
  const stencil = positionals[0] === 'stencil';
  const check = positionals[0] === 'check';
  const inspect = positionals[0] === 'inspect';
  const halfedges = positionals[0] === 'halfedges';
  const figure = positionals[0] === 'figure';
  const inputs = stencil || check || inspect || halfedges || figure ? positionals.slice(1) : positionals;
  if (check && inputs.length !== 2) throw new UsageError('subdiv check takes two files: CONTROL RESULT');
  if (!check && inputs.length !== 1) {
    throw new UsageError(inputs.length === 0 ? 'no INPUT file given' : 'give exactly one INPUT file');
  }
  const command = stencil
    ? 'stencil'
    : check
      ? 'check'
      : inspect
        ? 'inspect'
        : halfedges
          ? 'halfedges'
          : figure
            ? 'figure'
            : 'subdivide';
  const computations = ['self-intersections', 'sphere', 'hull', 'width', 'all'] as const;
  const drawing = ['view', 'mode', 'control-mesh', 'curves', 'size', 'line-width', 'transparent'] as const;
  const refused = {
    stencil: ['output', 'stats', 'levels', 'tolerance', ...computations, ...drawing],
    check: ['output', 'stats', 'level', 'vertex', ...computations, ...drawing],
    inspect: ['output', 'stats', 'level', 'vertex', 'tolerance', ...drawing],
    halfedges: ['output', 'stats', 'level', 'vertex', 'tolerance', ...computations, ...drawing],
    figure: ['stats', 'level', 'vertex', 'tolerance', ...computations],
    subdivide: ['level', 'vertex', 'tolerance', ...computations, ...drawing],
  } as const;
  for (const name of refused[command]) {
    if (values[name] !== undefined) {
      throw new UsageError(
        command === 'subdivide' ? `--${name} belongs to another command` : `subdiv ${command} takes no --${name}`,
      );
    }
  }
  // A decimal number: Number() would read "" and " " as 0 and "0x10" as 16.
  const tolerance =
    values.tolerance === undefined
      ? DEFAULT_TOLERANCE
      : /^\s*[+]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?\s*$/.test(values.tolerance)
        ? Number(values.tolerance)
        : Number.NaN;
  if (!(tolerance >= 0) || !Number.isFinite(tolerance)) {
    throw new UsageError(`--tolerance must be a number 0 or more, not "${values.tolerance}"`);
  }
  const creaseMethod = values['crease-method'] ?? null;
  if (creaseMethod !== null && !CREASE_METHODS.includes(creaseMethod as CreaseMethod)) {
    throw new UsageError(`--crease-method must be uniform or chaikin, not "${creaseMethod}"`);
  }
  const boundary = values.boundary ?? null;
  if (boundary !== null && !BOUNDARIES.includes(boundary as BoundaryInterpolation)) {
    throw new UsageError(`--boundary must be edge, edge-and-corner or none, not "${boundary}"`);
  }
  const levels = stencil
    ? count(values.level, '--level', 1)
    : count(values.levels ?? (inspect || halfedges || figure ? '0' : '1'), '--levels', 0);
  // inspect: every computation unless some are chosen.
  const chosen = computations.some((name) => values[name] === true);
  const wants = (name: (typeof computations)[number]) => !chosen || values.all === true || values[name] === true;
  const vertex = stencil ? count(values.vertex, '--vertex', 0) : 0;
  const rule = values.rule ?? null;
  if (rule !== null && values.scheme !== undefined && values.scheme !== 'custom') {
    throw new UsageError(`--rule gives the rules of --scheme custom, not of ${values.scheme}`);
  }
  const scheme = values.scheme ?? (rule !== null ? 'custom' : 'catmull-clark');
  if (scheme === 'custom' && rule === null) throw new UsageError('--scheme custom needs --rule FILE.json');
  return {
    command,
    input: inputs[0],
    result: check ? inputs[1] : '',
    tolerance,
    scheme,
    levels,
    triangulate: values.triangulate === true,
    rule,
    fixedBoundary: values['fixed-boundary'] === true,
    creaseMethod: creaseMethod as CreaseMethod | null,
    boundary: boundary as BoundaryInterpolation | null,
    output: values.output === undefined || figure ? null : { path: values.output, format: outputFormat(values.output) },
    stats: values.stats === true,
    repairOrientation: values['repair-orientation'] === true,
    vertex,
    inspect: {
      selfIntersections: wants('self-intersections'),
      sphere: wants('sphere'),
      hull: wants('hull'),
      width: wants('width'),
    },
    figure: figure ? figureOptions(values) : null,
    help,
  };
}

/** `subdiv figure`'s drawing options and output, checked. */
function figureOptions(values: ReturnType<typeof parse>['values']): FigureOptions & { path: string } {
  const path = values.output;
  if (path === undefined) throw new UsageError('subdiv figure needs -o OUT.svg, OUT.pdf or OUT.eps');
  const format = /\.(svg|pdf|eps)$/i.exec(path)?.[1].toLowerCase() as FigureFormat | undefined;
  if (!format) throw new UsageError(`figure file ${path} must end in .svg, .pdf or .eps`);
  const view = values.view === undefined ? null : parseFigureView(values.view);
  if (view === null && values.view !== undefined) {
    throw new UsageError(
      `--view must be front, top, side, iso or a camera "px,py,pz,tx,ty,tz,ux,uy,uz" (as the app's links write it), not "${values.view}"`,
    );
  }
  const mode = values.mode ?? 'edges';
  if (!FIGURE_MODES.includes(mode as FigureMode)) {
    throw new UsageError(
      `--mode must be ${FIGURE_MODES.join(', ')} (a vector figure draws flat-shaded polygons), not "${mode}"`,
    );
  }
  const size = /^(\d{1,5})x(\d{1,5})$/.exec(values.size ?? '800x600');
  const [width, height] = size ? [Number(size[1]), Number(size[2])] : [0, 0];
  if (!(width >= 16 && height >= 16 && width <= 20000 && height <= 20000)) {
    throw new UsageError(
      `--size must be WIDTHxHEIGHT in pixels, 16 to 20000 each (e.g. 800x600), not "${values.size}"`,
    );
  }
  const lineWidth = values['line-width'] === undefined ? DEFAULT_LINE_WIDTH : parseLineWidth(values['line-width']);
  if (lineWidth === null) {
    throw new UsageError(
      `--line-width must be a number from ${MIN_LINE_WIDTH} to ${MAX_LINE_WIDTH}, not "${values['line-width']}"`,
    );
  }
  return {
    path,
    format,
    view,
    mode: mode as FigureMode,
    controlMesh: values['control-mesh'] === true,
    curves: values.curves === true,
    width,
    height,
    lineWidth,
    transparent: values.transparent === true,
  };
}

/** An integer option of at least `least` (required when `text` is undefined). */
function count(text: string | undefined, name: string, least: number): number {
  if (text === undefined) throw new UsageError(`subdiv stencil needs ${name}`);
  if (!/^\d+$/.test(text) || Number(text) < least) {
    throw new UsageError(`${name} must be an integer ${least} or more, not "${text}"`);
  }
  return Number(text);
}

const CREASE_METHODS: CreaseMethod[] = ['uniform', 'chaikin'];
const BOUNDARIES: BoundaryInterpolation[] = ['edge', 'edge-and-corner', 'none'];

/** `subdiv compare A B`: two files and no options. */
function compareArgs({ values, positionals }: ReturnType<typeof parse>): CliArgs {
  if (positionals.length !== 3) throw new UsageError('subdiv compare takes two files: A B');
  const given = Object.keys(values);
  if (given.length > 0) throw new UsageError(`subdiv compare takes no options, not --${given[0]}`);
  return { ...NO_OPTIONS, command: 'compare', input: positionals[1], result: positionals[2], scheme: '', help: false };
}

/** `subdiv info INPUT`: one file and no options but --repair-orientation (the others are subdividing's). */
function infoArgs({ values, positionals }: ReturnType<typeof parse>): CliArgs {
  if (positionals.length !== 2) throw new UsageError('subdiv info takes exactly one INPUT file');
  const given = Object.keys(values).filter((name) => name !== 'repair-orientation');
  if (given.length > 0) throw new UsageError(`subdiv info takes no options, not --${given[0]}`);
  return {
    ...NO_OPTIONS,
    command: 'info',
    input: positionals[1],
    scheme: 'catmull-clark',
    help: false,
    repairOrientation: values['repair-orientation'] === true,
  };
}

function parse(argv: string[]) {
  return parseArgs({
    args: argv,
    allowPositionals: true,
    strict: true,
    options: {
      scheme: { type: 'string' },
      levels: { type: 'string' },
      level: { type: 'string' },
      vertex: { type: 'string' },
      tolerance: { type: 'string' },
      triangulate: { type: 'boolean' },
      rule: { type: 'string' },
      'fixed-boundary': { type: 'boolean' },
      'crease-method': { type: 'string' },
      boundary: { type: 'string' },
      output: { type: 'string', short: 'o' },
      stats: { type: 'boolean' },
      'repair-orientation': { type: 'boolean' },
      'self-intersections': { type: 'boolean' },
      sphere: { type: 'boolean' },
      hull: { type: 'boolean' },
      width: { type: 'boolean' },
      all: { type: 'boolean' },
      view: { type: 'string' },
      mode: { type: 'string' },
      'control-mesh': { type: 'boolean' },
      curves: { type: 'boolean' },
      size: { type: 'string' },
      'line-width': { type: 'string' },
      transparent: { type: 'boolean' },
      help: { type: 'boolean', short: 'h' },
    },
  });
}
