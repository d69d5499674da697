/**
 * A small, safe arithmetic expression language for subdivision weights typed
 * by people (rule files, the rules panel). Never `eval`: text is tokenized and
 * parsed by hand into a tree that can only do arithmetic.
 *
 * Grammar (usual precedence, `^` binds tightest and to the right):
 *   expr   := term (('+' | '-') term)*
 *   term   := unary (('*' | '/') unary)*
 *   unary  := ('+' | '-') unary | power
 *   power  := atom ('^' unary)?
 *   atom   := number | name | func '(' expr ')' | '(' expr ')'
 *   number := digits ['.' digits] [('e' | 'E') ['+' | '-'] digits]  (or '.' digits ...)
 *   name   := 'pi' | a variable the caller allows ('n' valence, 'k' face degree, 'j' corner)
 *   func   := 'cos' | 'sin' | 'sqrt'
 * Anything else is refused with a SubdivError (code invalid_argument) that
 * names the offending text and its column.
 */
import { SubdivError } from './subdiv-error';

/** A parsed expression: evaluate it for given variable values. */
export interface Expression {
  /** The source text. */
  readonly text: string;
  /** Variables the expression uses (subset of the allowed ones). */
  readonly variables: ReadonlySet<string>;
  /** The value for `vars` (missing variables are an error; the result may be NaN or ±Infinity). */
  evaluate(vars: Readonly<Record<string, number>>): number;
}

type Node =
  | { kind: 'num'; value: number }
  | { kind: 'var'; name: string }
  | { kind: 'neg'; arg: Node }
  | { kind: 'bin'; op: '+' | '-' | '*' | '/' | '^'; left: Node; right: Node }
  | { kind: 'call'; fn: 'cos' | 'sin' | 'sqrt'; arg: Node };

type Token =
  | { kind: 'num'; value: number; pos: number; text: string }
  | { kind: 'name'; name: string; pos: number; text: string }
  | { kind: 'op'; op: string; pos: number; text: string }
  | { kind: 'end'; pos: number; text: string };

const FUNCTIONS = new Set(['cos', 'sin', 'sqrt']);
const MAX_LENGTH = 1000;

function fail(text: string, message: string): never {
  throw new SubdivError('invalid_argument', `expression "${text}": ${message}`);
}

/**
 * The 1-based column of UTF-16 offset `i` in `text`, counted in characters
 * (code points) as an editor shows them: "𝑥" before a mistake is one column.
 */
function column(text: string, i: number): number {
  return [...text.slice(0, i)].length + 1;
}

function tokenize(text: string): Token[] {
  const tokens: Token[] = [];
  let i = 0;
  while (i < text.length) {
    const c = text[i];
    if (c === ' ' || c === '\t') {
      i++;
      continue;
    }
    const number = /^(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?/.exec(text.slice(i));
    if (number) {
      tokens.push({ kind: 'num', value: Number(number[0]), pos: i, text: number[0] });
      i += number[0].length;
      continue;
    }
    const name = /^[A-Za-z_][A-Za-z0-9_]*/.exec(text.slice(i));
    if (name) {
      tokens.push({ kind: 'name', name: name[0], pos: i, text: name[0] });
      i += name[0].length;
      continue;
    }
    if ('+-*/^()'.includes(c)) {
      tokens.push({ kind: 'op', op: c, pos: i, text: c });
      i++;
      continue;
    }
    // The whole character, not half of a surrogate pair.
    fail(text, `unexpected character "${String.fromCodePoint(text.codePointAt(i) ?? 0)}" at column ${column(text, i)}`);
  }
  tokens.push({ kind: 'end', pos: text.length, text: 'the end' });
  return tokens;
}

/**
 * Parses `text`. `allowed` names the variables it may use besides `pi`
 * (e.g. `['n']` for a vertex rule). Throws SubdivError('invalid_argument').
 */
export function parseExpression(text: string, allowed: readonly string[] = ['n', 'k']): Expression {
  // Named by its type: String() of an object can throw (a toString that is not a function).
  if (typeof text !== 'string') {
    throw new SubdivError('invalid_argument', `expression: not a string but ${text === null ? 'null' : typeof text}`);
  }
  if (text.length > MAX_LENGTH)
    fail(`${[...text.slice(0, 40)].slice(0, 20).join('')}...`, `longer than ${MAX_LENGTH} characters`);
  if (text.trim() === '') fail(text, 'empty');
  const tokens = tokenize(text);
  let at = 0;
  const used = new Set<string>();
  const peek = () => tokens[at];
  const isOp = (op: string) => {
    const t = peek();
    return t.kind === 'op' && t.op === op;
  };
  const where = (t: Token) => (t.kind === 'end' ? 'at the end' : `"${t.text}" at column ${column(text, t.pos)}`);

  const expr = (): Node => {
    let left = term();
    while (isOp('+') || isOp('-')) {
      const op = (tokens[at++] as { op: '+' | '-' }).op;
      left = { kind: 'bin', op, left, right: term() };
    }
    return left;
  };
  const term = (): Node => {
    let left = unary();
    while (isOp('*') || isOp('/')) {
      const op = (tokens[at++] as { op: '*' | '/' }).op;
      left = { kind: 'bin', op, left, right: unary() };
    }
    return left;
  };
  const unary = (): Node => {
    if (isOp('-')) {
      at++;
      return { kind: 'neg', arg: unary() };
    }
    if (isOp('+')) {
      at++;
      return unary();
    }
    return power();
  };
  const power = (): Node => {
    const base = atom();
    if (isOp('^')) {
      at++;
      return { kind: 'bin', op: '^', left: base, right: unary() };
    }
    return base;
  };
  const expect = (op: string) => {
    if (!isOp(op)) fail(text, `expected "${op}" but found ${where(peek())}`);
    at++;
  };
  const atom = (): Node => {
    const t = peek();
    if (t.kind === 'num') {
      at++;
      return { kind: 'num', value: t.value };
    }
    if (t.kind === 'name') {
      at++;
      if (FUNCTIONS.has(t.name)) {
        expect('(');
        const arg = expr();
        expect(')');
        return { kind: 'call', fn: t.name as 'cos' | 'sin' | 'sqrt', arg };
      }
      if (t.name === 'pi') return { kind: 'num', value: Math.PI };
      if (allowed.includes(t.name)) {
        used.add(t.name);
        return { kind: 'var', name: t.name };
      }
      const known = ['pi', ...allowed].join(', ');
      fail(
        text,
        `unknown name "${t.name}" at column ${column(text, t.pos)} (allowed: numbers, ${known}, cos, sin, sqrt, + - * / ^ and parentheses)`,
      );
    }
    if (isOp('(')) {
      at++;
      const inner = expr();
      expect(')');
      return inner;
    }
    return fail(text, `expected a number, a name or "(" but found ${where(t)}`);
  };

  const root = expr();
  if (peek().kind !== 'end') fail(text, `unexpected ${where(peek())}`);

  const evaluate = (node: Node, vars: Readonly<Record<string, number>>): number => {
    switch (node.kind) {
      case 'num':
        return node.value;
      case 'var': {
        const v = vars[node.name];
        if (typeof v !== 'number') fail(text, `no value for "${node.name}"`);
        return v;
      }
      case 'neg':
        return -evaluate(node.arg, vars);
      case 'call': {
        const x = evaluate(node.arg, vars);
        return node.fn === 'cos' ? Math.cos(x) : node.fn === 'sin' ? Math.sin(x) : Math.sqrt(x);
      }
      case 'bin': {
        const a = evaluate(node.left, vars);
        const b = evaluate(node.right, vars);
        switch (node.op) {
          case '+':
            return a + b;
          case '-':
            return a - b;
          case '*':
            return a * b;
          case '/':
            return a / b;
          case '^':
            return a ** b;
        }
      }
    }
  };

  return {
    text,
    variables: used,
    evaluate: (vars) => evaluate(root, vars),
  };
}

/** Parses and evaluates `text` once (see {@link parseExpression}). */
export function evaluateExpression(
  text: string,
  vars: Readonly<Record<string, number>> = {},
  allowed: readonly string[] = Object.keys(vars),
): number {
  return parseExpression(text, allowed).evaluate(vars);
}
