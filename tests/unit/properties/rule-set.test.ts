/**
 * Properties of rule sets (web/core/rule-set.ts), with fast-check: any
 * text, JSON value or object handed to parseRuleSetText / parseRuleSet /
 * compileRuleSet is accepted or refused with a SubdivError
 * ('invalid_argument') that says "rule set: WHERE: WHAT"; and a valid rule
 * set written by ruleSetToText reads back equal, and compiles to the same
 * tables.
 */
import fc from 'fast-check';
import './seed';
import { describe, expect, it } from 'vitest';
import {
  compileRuleSet,
  parseRuleSet,
  parseRuleSetText,
  type RuleHost,
  type RuleSet,
  ruleSetToText,
  type ValenceWeight,
  type Weight,
} from '../../../web/core/rule-set';
import { SubdivError } from '../../../web/core/subdiv-error';
import { anything } from './arbitraries';

/** Where in the file, then what is wrong there. */
const REFUSAL =
  /^rule set: (file|format|version|name|description|host|vertex|edge|corner|border)[\w.[\]"]*: \S[\s\S]*$/;

/** Runs `f`; a SubdivError must be a rule-set refusal (anything else thrown fails the property). */
function acceptedOrRefused(f: () => unknown): boolean {
  try {
    f();
    return true;
  } catch (error) {
    if (!(error instanceof SubdivError)) throw error;
    expect(error.code).toBe('invalid_argument');
    expect(error.message).toMatch(REFUSAL);
    return false;
  }
}

const HOSTS: RuleHost[] = ['pqq', 'ptq', 'dqq', 'sqrt3'];

/** Formulas in the given variables, and numbers (finite; -0 is written as 0 by JSON, so left out). */
function weight(vars: readonly string[]): fc.Arbitrary<Weight> {
  const names = ['pi', ...vars];
  return fc.oneof(
    fc.double({ noNaN: true, noDefaultInfinity: true }).map((x) => x + 0),
    fc.integer({ min: -20, max: 20 }),
    fc.tuple(fc.integer({ min: -9, max: 9 }), fc.integer({ min: 1, max: 64 })).map(([p, q]) => `${p}/${q}`),
    fc
      .tuple(fc.constantFrom(...names), fc.constantFrom('+', '-', '*', '/'), fc.integer({ min: 1, max: 9 }))
      .map(([a, op, b]) => `(${a} ${op} ${b})/8`),
    fc
      .constantFrom('3/(8*n)', '5/8 - (3/8 + cos(2*pi/n)/4)^2', 'sqrt(2)/4', '(3 + 2*cos(2*pi*j/k))/(4*k)')
      .filter((f) => [...f.matchAll(/[a-z]+/g)].every(([w]) => ['cos', 'sqrt', 'pi', ...vars].includes(w))),
  );
}

const valenceWeight: fc.Arbitrary<ValenceWeight> = fc.oneof(
  weight(['n']),
  fc
    .tuple(
      fc.dictionary(fc.integer({ min: 1, max: 200 }).map(String), weight(['n']), { minKeys: 0, maxKeys: 4 }),
      fc.option(weight(['n']), { nil: undefined }),
    )
    .map(([table, fallback]) => (fallback === undefined ? table : { ...table, default: fallback })),
);

const validRuleSet: fc.Arbitrary<RuleSet> = fc
  .record({
    host: fc.constantFrom(...HOSTS),
    name: fc.option(fc.string(), { nil: undefined }),
    description: fc.option(fc.string({ unit: 'grapheme' }), { nil: undefined }),
    self: valenceWeight,
    neighbour: valenceWeight,
    face: fc.option(valenceWeight, { nil: undefined }),
    end: weight([]),
    wing: weight([]),
    cornerSelf: weight(['k']),
    cornerOther: weight(['k', 'j']),
    borderVertex: fc.option(fc.tuple(weight([]), weight([]), weight([])), { nil: undefined }),
    borderEdge: fc.option(fc.tuple(weight([]), weight([]), weight([]), weight([])), { nil: undefined }),
    borderCorner: fc.option(fc.tuple(weight([]), weight([])), { nil: undefined }),
  })
  .map((r) => {
    const rules: RuleSet = { host: r.host };
    if (r.name !== undefined) rules.name = r.name;
    if (r.description !== undefined) rules.description = r.description;
    if (r.host !== 'dqq') {
      rules.vertex = { self: r.self, neighbour: r.neighbour };
      if (r.host === 'pqq' && r.face !== undefined) rules.vertex.face = r.face;
    }
    if (r.host === 'pqq' || r.host === 'ptq') rules.edge = { end: r.end, wing: r.wing };
    if (r.host === 'dqq') {
      rules.corner = { self: r.cornerSelf, other: r.cornerOther };
      if (r.borderCorner) rules.border = { corner: r.borderCorner };
    } else if (r.borderVertex || r.borderEdge) {
      rules.border = {};
      if (r.borderVertex) rules.border.vertex = r.borderVertex;
      if (r.borderEdge) rules.border.edge = r.borderEdge;
    }
    return rules;
  });

/** Rule sets with one part swapped for something else: close enough to valid to reach every check. */
const nearlyValid = fc
  .tuple(
    validRuleSet,
    fc.constantFrom('host', 'vertex', 'edge', 'corner', 'border', 'format', 'version', 'name', 'extra'),
    fc.oneof(fc.jsonValue(), weight(['n', 'k', 'j']), fc.constantFrom(...HOSTS)),
    fc.constantFrom('self', 'neighbour', 'face', 'end', 'wing', 'other', 'vertex', 'edge', 'corner', '6', 'default'),
  )
  .map(([rules, part, value, inner]) => {
    const out: Record<string, unknown> = { ...rules };
    const current = out[part];
    if (current !== null && typeof current === 'object' && !Array.isArray(current)) {
      out[part] = { ...current, [inner]: value };
    } else {
      out[part] = value;
    }
    return out;
  });

describe('rule sets: any input', () => {
  it.each([
    ['any text', fc.string({ unit: 'binary' })],
    ['any JSON text', fc.json()],
    ['valid rule files', validRuleSet.map(ruleSetToText)],
    ['rule files with a part swapped', nearlyValid.map((r) => JSON.stringify(r))],
  ] as [string, fc.Arbitrary<string>][])('%s: read or refused with "rule set: WHERE: WHAT"', (_, texts) => {
    fc.assert(
      fc.property(texts, (text) => {
        acceptedOrRefused(() => parseRuleSetText(text));
      }),
      { numRuns: 200 },
    );
  });

  it('any JSON value, and rule sets with a part swapped, are accepted or refused; what is accepted compiles or is refused', () => {
    fc.assert(
      fc.property(fc.oneof(fc.jsonValue(), nearlyValid), (json) => {
        if (acceptedOrRefused(() => parseRuleSet(json))) {
          acceptedOrRefused(() => compileRuleSet(json as unknown as RuleSet, { maxValence: 8, maxDegree: 8 }));
        }
      }),
      { numRuns: 500 },
    );
  });

  it('any value built in code (bigints, cycles, null prototypes, maps, dates) is accepted or refused', () => {
    const cyclic: Record<string, unknown> = { host: 'pqq' };
    cyclic.self = cyclic;
    fc.assert(
      fc.property(
        anything,
        fc.constantFrom('format', 'version', 'host', 'name', 'vertex', 'edge', 'corner', 'border'),
        fc.boolean(),
        (value, key, cycle) => {
          acceptedOrRefused(() => parseRuleSet(value));
          // The same value in each field of an otherwise valid rule set, or a cycle there.
          const rules: Record<string, unknown> = {
            host: 'ptq',
            vertex: { self: 0.5, neighbour: 0.5 / 6 },
            edge: { end: 0.375, wing: 0.125 },
          };
          rules[key] = cycle ? cyclic : value;
          acceptedOrRefused(() => parseRuleSet(rules));
        },
      ),
      { numRuns: 500 },
    );
  });
});

describe('rule sets: deep nesting', () => {
  it('arrays or objects nested up to 100,000 deep in any field are refused, never a stack overflow', () => {
    const fields = [
      'format',
      'version',
      'host',
      'name',
      'vertex',
      'edge',
      'corner',
      'border',
      'vertex.self',
      'edge.end',
    ];
    fc.assert(
      fc.property(
        fc.integer({ min: 1, max: 100_000 }),
        fc.constantFrom(...fields),
        fc.boolean(),
        (depth, field, arrays) => {
          const deep = arrays
            ? `${'['.repeat(depth)}${']'.repeat(depth)}`
            : `${'{"a":'.repeat(depth)}1${'}'.repeat(depth)}`;
          const [outer, inner] = field.split('.');
          const value = inner ? `{"${inner}": ${deep}}` : deep;
          const text = `{"host": "pqq", "vertex": {"self": 0.5, "neighbour": 0.1}, "edge": {"end": 0.4, "wing": 0.1}, "${outer}": ${value}}`;
          expect(acceptedOrRefused(() => parseRuleSetText(text))).toBe(false);
        },
      ),
      { numRuns: 15 },
    );
  });
});

describe('rule sets: shrunk counterexamples', () => {
  const loop = { host: 'ptq', vertex: { self: 0.5, neighbour: 0.5 / 6 }, edge: { end: 0.375, wing: 0.125 } };

  it('a cycle or a bigint where a string belongs is named, not a TypeError from JSON.stringify', () => {
    const cyclic: Record<string, unknown> = {};
    cyclic.self = cyclic;
    expect(() => parseRuleSet({ ...loop, format: cyclic })).toThrow(
      'rule set: format: expected "subdivlab-rules", got an object',
    );
    expect(() => parseRuleSet({ ...loop, version: 1n })).toThrow('rule set: version: expected 1, got 1n');
    expect(() => parseRuleSet({ ...loop, host: [cyclic] })).toThrow(
      'rule set: host: expected one of pqq, ptq, dqq, sqrt3, got an array',
    );
  });

  it('a long value is quoted cut to 80 characters', () => {
    expect(() => parseRuleSet({ ...loop, host: 'x'.repeat(10_000) })).toThrow(
      `rule set: host: expected one of pqq, ptq, dqq, sqrt3, got "${'x'.repeat(79)}…`,
    );
  });
});

describe('rule sets: valid ones round-trip', () => {
  it('ruleSetToText then parseRuleSetText gives the rule set back, and the same tables', () => {
    fc.assert(
      fc.property(validRuleSet, (rules) => {
        const back = parseRuleSetText(ruleSetToText(rules));
        expect(back).toEqual({ format: 'subdivlab-rules', version: 1, ...rules });
        const limits = { maxValence: 12, maxDegree: 9 };
        const compile = (r: RuleSet) => {
          try {
            return compileRuleSet(r, limits);
          } catch (error) {
            if (!(error instanceof SubdivError)) throw error;
            return error.message;
          }
        };
        expect(compile(back)).toEqual(compile(rules));
      }),
      { numRuns: 300 },
    );
  });
});
