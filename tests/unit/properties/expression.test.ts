/**
 * Properties of the weight expression parser (web/core/expression.ts), with
 * fast-check: any text is parsed or refused with a SubdivError
 * ('invalid_argument') whose message quotes the text and names what is
 * wrong where (a column that points at the named token); deep nesting is
 * refused or parsed without exhausting the stack; and an expression tree
 * printed with the fewest parentheses the grammar allows parses back to the
 * same tree (same value, bit for bit, at random points).
 */
import fc from 'fast-check';
import './seed';
import { describe, expect, it } from 'vitest';
import { parseExpression } from '../../../web/core/expression';
import { SubdivError } from '../../../web/core/subdiv-error';

/** The outcome of parsing `text`: the expression, or the SubdivError (anything else is rethrown). */
function parse(text: string, allowed: readonly string[] = ['n', 'k']) {
  try {
    return { ok: true as const, expression: parseExpression(text, allowed) };
  } catch (error) {
    if (!(error instanceof SubdivError)) throw error;
    return { ok: false as const, error };
  }
}

/** What a refusal says: `expression "TEXT": PROBLEM`, the problem one of the documented kinds. */
const PROBLEM =
  /^expression "[\s\S]*": (empty|longer than 1000 characters|unexpected character "[\s\S]+" at column \d+|expected "[()]" but found [\s\S]+|unknown name "[A-Za-z_]\w*" at column \d+ \(allowed: [\s\S]+\)|expected a number, a name or "\(" but found [\s\S]+|unexpected "[\s\S]+" at column \d+|unexpected at the end)$/;

/** No lone surrogate: in 'u' mode a pair is one code point, and \p{Cs} matches only a lone half. */
const wellFormed = (s: string) => !/\p{Cs}/u.test(s);

/** Checks a refusal of `text`: its code, its form, and that a column it names holds what it quotes. */
function expectNamedProblem(text: string, error: SubdivError): void {
  expect(error.code).toBe('invalid_argument');
  expect(error.message).toMatch(PROBLEM);
  // Whole characters: never half of a surrogate pair from a well-formed text.
  if (wellFormed(text)) expect(wellFormed(error.message)).toBe(true);
  // Columns count characters (code points), as an editor shows them.
  const at = /(?:character|found|unexpected|name) "([\s\S]+)" at column (\d+)/.exec(
    error.message.slice(error.message.lastIndexOf('": ') + 3),
  );
  if (at)
    expect(
      [...text]
        .slice(Number(at[2]) - 1)
        .join('')
        .startsWith(at[1]),
    ).toBe(true);
}

/** Tokens of the language and near misses, for texts that get past the tokenizer. */
const PIECES = [
  '1',
  '2.5',
  '.5',
  '1e3',
  '3E-2',
  '1.',
  'n',
  'k',
  'j',
  'pi',
  'sqrt',
  'cos',
  'sin',
  'tan',
  'x',
  '(',
  ')',
  '+',
  '-',
  '*',
  '/',
  '^',
  ' ',
  '\t',
  '.',
  'e',
  ',',
  '**',
];
const almostExpressions = fc.array(fc.constantFrom(...PIECES), { maxLength: 30 }).map((p) => p.join(''));

const anyText = fc.oneof(
  fc.string({ unit: 'binary', maxLength: 60 }),
  fc.string({ unit: 'grapheme', maxLength: 60 }),
  fc.string({ unit: 'binary', minLength: 990, maxLength: 1100 }),
  almostExpressions,
);

describe('expression parser: any text', () => {
  it('is parsed, or refused with a SubdivError naming the problem and its column', () => {
    fc.assert(
      fc.property(anyText, (text) => {
        const r = parse(text);
        if (!r.ok) {
          expectNamedProblem(text, r.error);
          return;
        }
        // What parses uses only the allowed names and evaluates to a number for any values of them.
        expect([...r.expression.variables].every((v) => v === 'n' || v === 'k')).toBe(true);
        expect(typeof r.expression.evaluate({ n: 5, k: 4 })).toBe('number');
      }),
      { numRuns: 1000 },
    );
  });

  it('refuses what is not a string with the documented error', () => {
    fc.assert(
      fc.property(fc.anything(), (value) => {
        fc.pre(typeof value !== 'string');
        const r = parse(value as string);
        expect(r.ok).toBe(false);
        if (!r.ok) {
          expect(r.error.code).toBe('invalid_argument');
          expect(r.error.message).toBe(`expression: not a string but ${value === null ? 'null' : typeof value}`);
        }
      }),
    );
  });

  it('refuses an object whose toString is not a function (shrunk counterexample)', () => {
    expect(() => parseExpression({ toString: 0 } as unknown as string)).toThrow('expression: not a string but object');
    expect(() => parseExpression(null as unknown as string)).toThrow('expression: not a string but null');
  });

  // Shrunk counterexamples, kept as plain cases.
  it('names a character beyond the BMP whole, at its column in characters', () => {
    expect(() => parseExpression('\u{10000}')).toThrow(
      'expression "\u{10000}": unexpected character "\u{10000}" at column 1',
    );
    expect(() => parseExpression('\u{1D465} + \u{1F600}')).toThrow('unexpected character "\u{1D465}" at column 1');
    expect(() => parseExpression('1 + \u{1F600}')).toThrow('unexpected character "\u{1F600}" at column 5');
    expect(() => parseExpression('\u{1F600}\u{1F600} zz', [])).toThrow('unexpected character "\u{1F600}" at column 1');
    expect(() => parseExpression(`${'\u{1F600}'.repeat(600)}`)).toThrow(
      `expression "${'\u{1F600}'.repeat(20)}...": longer than 1000 characters`,
    );
    expect(() => parseExpression('\u00e9 + n x')).toThrow('unexpected character "\u00e9" at column 1');
    expect(() => parseExpression('n + \u00e9', ['n'])).toThrow('at column 5');
  });
});

describe('expression parser: nesting', () => {
  const nested = (depth: number, open: string, close: string) => `${open.repeat(depth)}n${close.repeat(depth)}`;

  it('parentheses, unary signs and functions to any depth: parsed and right, or refused for length; no stack overflow', () => {
    const forms: [string, string, (x: number, d: number) => number][] = [
      ['(', ')', (x) => x],
      ['-', '', (x, d) => (d % 2 === 0 ? x : -x)],
      ['+(', ')', (x) => x],
      ['sqrt(', ')', (x, d) => x ** (1 / 2 ** d)],
      ['2^', '', () => Number.NaN],
    ];
    fc.assert(
      fc.property(fc.integer({ min: 1, max: 20_000 }), fc.constantFrom(...forms.keys()), (depth, which) => {
        const [open, close, value] = forms[which];
        const text = nested(depth, open, close);
        const r = parse(text);
        if (text.length > 1000) {
          expect(r.ok).toBe(false);
          if (!r.ok) expect(r.error.message).toMatch(/: longer than 1000 characters$/);
          return;
        }
        expect(r.ok).toBe(true);
        if (!r.ok || open === '2^') return;
        const got = r.expression.evaluate({ n: 7, k: 0 });
        expect(Math.abs(got - value(7, depth))).toBeLessThanOrEqual(1e-12 * Math.abs(value(7, depth)));
      }),
      { numRuns: 300 },
    );
  });

  it('the deepest nesting the length allows parses and evaluates', () => {
    expect(parseExpression(nested(499, '(', ')'), ['n']).evaluate({ n: 3 })).toBe(3);
    expect(parseExpression(`${'-'.repeat(999)}n`, ['n']).evaluate({ n: 3 })).toBe(-3);
    // ^ is right-associative: 2^(2^(2^3)) = 2^256; 499 of them overflow to Infinity.
    expect(parseExpression(`${'2^'.repeat(3)}3`, []).evaluate({})).toBe(2 ** 256);
    expect(parseExpression(`${'2^'.repeat(499)}0`, []).evaluate({})).toBe(Number.POSITIVE_INFINITY);
    expect(() => parseExpression(nested(10_000, '(', ')'), ['n'])).toThrow(/longer than 1000 characters/);
  });
});

/** Expression trees of the documented grammar. */
type Tree =
  | { kind: 'num'; value: number }
  | { kind: 'var'; name: 'n' | 'k' }
  | { kind: 'pi' }
  | { kind: 'neg'; arg: Tree }
  | { kind: 'bin'; op: '+' | '-' | '*' | '/' | '^'; left: Tree; right: Tree }
  | { kind: 'call'; fn: 'cos' | 'sin' | 'sqrt'; arg: Tree };

const trees = fc.letrec<{ tree: Tree }>((tie) => ({
  tree: fc.oneof(
    { depthSize: 'small', withCrossShrink: true },
    fc.oneof(
      fc.integer({ min: 0, max: 100 }).map((value): Tree => ({ kind: 'num', value })),
      fc.double({ min: 0, max: 1e300, noNaN: true }).map((value): Tree => ({ kind: 'num', value: value + 0 })),
    ),
    fc.constantFrom<Tree>({ kind: 'var', name: 'n' }, { kind: 'var', name: 'k' }, { kind: 'pi' }),
    tie('tree').map((arg): Tree => ({ kind: 'neg', arg })),
    fc
      .record({ op: fc.constantFrom('+', '-', '*', '/', '^'), left: tie('tree'), right: tie('tree') })
      .map(({ op, left, right }): Tree => ({ kind: 'bin', op: op as '+', left, right })),
    fc
      .record({ fn: fc.constantFrom('cos', 'sin', 'sqrt'), arg: tie('tree') })
      .map(({ fn, arg }): Tree => ({ kind: 'call', fn: fn as 'cos', arg })),
  ),
})).tree;

/**
 * Precedence in the grammar: + - 1, * / 2, unary minus 3, ^ 4, atoms 5.
 * `^` takes an atom on its left and a unary on its right (so -2^2 is -(2^2)
 * and 2^-1 needs no parentheses); + - * / are left-associative.
 */
function print(tree: Tree, space: string): { text: string; prec: number } {
  const wrap = (t: Tree, least: number) => {
    const p = print(t, space);
    return p.prec >= least ? p.text : `(${p.text})`;
  };
  switch (tree.kind) {
    case 'num':
      return { text: String(tree.value), prec: 5 };
    case 'var':
      return { text: tree.name, prec: 5 };
    case 'pi':
      return { text: 'pi', prec: 5 };
    case 'neg':
      return { text: `-${space}${wrap(tree.arg, 3)}`, prec: 3 };
    case 'call':
      return { text: `${tree.fn}(${print(tree.arg, space).text})`, prec: 5 };
    case 'bin': {
      const prec = tree.op === '^' ? 4 : tree.op === '*' || tree.op === '/' ? 2 : 1;
      const left = wrap(tree.left, tree.op === '^' ? 5 : prec);
      const right = wrap(tree.right, tree.op === '^' ? 3 : prec + 1);
      return { text: `${left}${space}${tree.op}${space}${right}`, prec };
    }
  }
}

function value(tree: Tree, n: number, k: number): number {
  switch (tree.kind) {
    case 'num':
      return tree.value;
    case 'var':
      return tree.name === 'n' ? n : k;
    case 'pi':
      return Math.PI;
    case 'neg':
      return -value(tree.arg, n, k);
    case 'call': {
      const x = value(tree.arg, n, k);
      return tree.fn === 'cos' ? Math.cos(x) : tree.fn === 'sin' ? Math.sin(x) : Math.sqrt(x);
    }
    case 'bin': {
      const a = value(tree.left, n, k);
      const b = value(tree.right, n, k);
      return tree.op === '+'
        ? a + b
        : tree.op === '-'
          ? a - b
          : tree.op === '*'
            ? a * b
            : tree.op === '/'
              ? a / b
              : a ** b;
    }
  }
}

describe('expression parser: valid expressions round-trip', () => {
  it('a tree printed with the fewest parentheses parses back to the same values', () => {
    fc.assert(
      fc.property(
        trees,
        fc.constantFrom('', ' ', '\t'),
        fc.array(fc.tuple(fc.integer({ min: 3, max: 64 }), fc.double({ noNaN: true })), {
          minLength: 1,
          maxLength: 4,
        }),
        (tree, space, points) => {
          const { text } = print(tree, space);
          fc.pre(text.length <= 1000);
          const r = parse(text);
          if (!r.ok) throw new Error(`${text}: ${r.error.message}`);
          for (const [n, k] of points) {
            const want = value(tree, n, k);
            const got = r.expression.evaluate({ n, k });
            // Same tree, same operations in the same order: the same double (NaN for NaN; 0 and -0 print alike).
            expect(Object.is(got, want) || got === want).toBe(true);
          }
        },
      ),
      { numRuns: 1000 },
    );
  });
});

describe('expression parser: evaluation', () => {
  it('without a value for a variable it uses is the documented error', () => {
    fc.assert(
      fc.property(trees, (tree) => {
        const text = `${print(tree, ' ').text} + n`;
        fc.pre(text.length <= 1000);
        const e = parseExpression(text, ['n', 'k']);
        expect(e.variables.has('n')).toBe(true);
        expect(() => e.evaluate({ k: 1 })).toThrow(SubdivError);
        expect(() => e.evaluate({ k: 1 })).toThrow(/: no value for "[nk]"$/);
      }),
    );
  });
});
