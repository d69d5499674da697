/**
 * Properties of what a page hands an embedded viewer, with fast-check: the
 * `<subdiv-viewer>` attributes (web/embed/embed-state.ts, read; and
 * web/embed/viewer-attributes.ts, the properties that write them) and the
 * iframe route's postMessage commands (web/embed/embed-messages.ts). Any
 * attribute text reads as a state, a bad value named in `problems` under its
 * attribute; any message is a command or refused with a reason, never a
 * throw; a valid state set through the element's properties reads back.
 */
import fc from 'fast-check';
import './seed';
import { beforeAll, describe, expect, it } from 'vitest';
import { checkCommand } from '../../../web/embed/embed-messages';
import { EMBED_TOOLS, readEmbedState } from '../../../web/embed/embed-state';
import type { ViewerAttributes } from '../../../web/embed/viewer-attributes';
import { MAX_LINE_WIDTH, MIN_LINE_WIDTH } from '../../../web/render/line-style';
import { RENDER_MODES } from '../../../web/render/render-mode';
import { checkedView, formatViewString } from '../../../web/render/view-state';
import { PANE_SCHEMES, SCHEME_NAMES } from '../../../web/viewer/scheme-info';
import { CONTROLS_MODES, MAX_PARAM_LEVELS, OVERLAY_KEYS } from '../../../web/viewer/viewer-params';
import { anything } from './arbitraries';

/**
 * HTMLElement's attribute storage, for Node: the element class under test
 * extends it and uses nothing else of the DOM (get, set, remove; set turns
 * the value into a string, as the DOM does).
 */
class AttributeStore {
  readonly attributes = new Map<string, string>();
  getAttribute(name: string): string | null {
    return this.attributes.get(name) ?? null;
  }
  setAttribute(name: string, value: unknown): void {
    this.attributes.set(name, String(value));
  }
  removeAttribute(name: string): void {
    this.attributes.delete(name);
  }
}

let Element: new () => ViewerAttributes;
beforeAll(async () => {
  (globalThis as { HTMLElement?: unknown }).HTMLElement ??= AttributeStore;
  Element = (await import('../../../web/embed/viewer-attributes'))
    .ViewerAttributes as unknown as new () => ViewerAttributes;
});

const ATTRIBUTES = [
  'src',
  'scheme',
  'levels',
  'render-mode',
  ...Object.values(OVERLAY_KEYS),
  'triangulate',
  'rules',
  'view',
  'controls',
  'alt',
  'background',
  'tool',
  'vertex',
  'split',
  'beside',
  'distance',
  'line-width',
];

const attributeValue = fc.oneof(
  fc.string({ unit: 'binary', maxLength: 16 }),
  fc.constantFrom(
    '',
    '0',
    '1',
    ' 2 ',
    '1e-7',
    '0.5',
    '.5',
    '+1',
    '-0',
    'loop',
    'custom',
    'edges',
    'full',
    'basis',
    '0,0,5,0,0,0,0,1,0',
    'red',
  ),
);

describe('element attributes: any text', () => {
  it('reads as a state; each problem names an attribute that was given, once, in a sentence', () => {
    fc.assert(
      fc.property(fc.dictionary(fc.constantFrom(...ATTRIBUTES, 'other'), attributeValue), (given) => {
        const state = readEmbedState((name) => (Object.hasOwn(given, name) ? given[name] : null));
        const named = state.problems.map((p) => p.attribute);
        expect(new Set(named).size).toBe(named.length);
        for (const { attribute, message } of state.problems) {
          // A custom scheme without rules is named under rules, whether rules was given or not.
          if (attribute !== 'rules') expect(Object.hasOwn(given, attribute)).toBe(true);
          expect(message).toMatch(/^\S[\s\S]*\.$/);
        }
        expect(SCHEME_NAMES).toContain(state.scheme);
        expect(state.levels).toBeGreaterThanOrEqual(0);
        expect(state.levels).toBeLessThanOrEqual(MAX_PARAM_LEVELS);
        expect(state.split).toBeGreaterThanOrEqual(0);
        expect(state.split).toBeLessThanOrEqual(1);
        expect(state.lineWidth).toBeGreaterThanOrEqual(MIN_LINE_WIDTH);
        expect(state.lineWidth).toBeLessThanOrEqual(MAX_LINE_WIDTH);
        if (state.view) expect(checkedView(state.view)).toEqual(state.view);
      }),
      { numRuns: 500 },
    );
  });
});

const views = fc
  .record({
    position: fc.tuple(fc.double({ min: -50, max: 50, noNaN: true }), fc.integer(), fc.integer()),
    target: fc.tuple(fc.integer({ min: -3, max: 3 }), fc.integer({ min: -3, max: 3 }), fc.integer({ min: -3, max: 3 })),
    up: fc.constantFrom<[number, number, number]>([0, 1, 0], [0, 0, 1], [1, 1, 0]),
  })
  .filter((v) => checkedView(v) !== null);

describe('element attributes: set through the properties', () => {
  it('a valid state set through the properties reads back', () => {
    fc.assert(
      fc.property(
        fc.record({
          scheme: fc.constantFrom(...SCHEME_NAMES.filter((s) => s !== 'custom')),
          levels: fc.integer({ min: 0, max: MAX_PARAM_LEVELS }),
          renderMode: fc.constantFrom(...RENDER_MODES.map((m) => m.mode)),
          controlMesh: fc.boolean(),
          controlEdges: fc.boolean(),
          bbox: fc.boolean(),
          creases: fc.boolean(),
          triangulate: fc.boolean(),
          controls: fc.constantFrom(...CONTROLS_MODES),
          tool: fc.constantFrom(...EMBED_TOOLS),
          vertex: fc.option(fc.maxSafeNat()),
          split: fc.double({ min: 0, max: 1, noNaN: true }).map((t) => t + 0),
          beside: fc.uniqueArray(fc.constantFrom(...PANE_SCHEMES), { maxLength: 3 }),
          distance: fc.boolean(),
          lineWidth: fc.double({ min: MIN_LINE_WIDTH, max: MAX_LINE_WIDTH, noNaN: true }),
          view: views.map(formatViewString),
        }),
        (wanted) => {
          const element = new Element();
          Object.assign(element, wanted);
          const read = {
            ...Object.fromEntries(Object.keys(wanted).map((key) => [key, element[key as keyof ViewerAttributes]])),
          };
          expect(read).toEqual(wanted);
          expect(readEmbedState((name) => element.getAttribute(name)).problems).toEqual([]);
        },
      ),
      { numRuns: 500 },
    );
  });

  it('split takes every number from 0 to 1 as the property writes it (shrunk counterexample: 5e-324)', () => {
    const element = new Element();
    for (const t of [5e-324, 1e-7, 0.000001, 2.5e-10, 0, 1, 0.5]) {
      element.split = t;
      expect(element.split).toBe(t);
    }
    for (const bad of ['1e', 'e5', '1e+', '2', '-1e-7', '1.5e0', '0x1']) {
      element.setAttribute('split', bad);
      expect(element.split).toBe(1);
      expect(readEmbedState((name) => element.getAttribute(name)).problems).toEqual([
        { attribute: 'split', message: `split must be a number from 0 to 1, not "${bad}".` },
      ]);
    }
  });
});

const COMMANDS = [
  'load',
  'set-scheme',
  'subdivide',
  'set-level',
  'set-view',
  'set-render-mode',
  'set-overlay',
  'set-triangulate',
  'set-tool',
  'set-split',
];

/** Field values a command might carry, right or wrong. */
const field = fc.oneof(
  anything,
  fc.constantFrom(...SCHEME_NAMES, ...RENDER_MODES.map((m) => m.mode), ...Object.values(OVERLAY_KEYS), ...EMBED_TOOLS),
  fc.double(),
  fc.integer({ min: -2, max: 12 }),
  fc.boolean(),
  views,
  views.map(formatViewString),
  fc.string(),
);

const messages = fc.oneof(
  anything,
  fc.record(
    {
      subdivlab: fc.oneof(fc.constantFrom(...COMMANDS), anything),
      src: field,
      text: field,
      name: field,
      scheme: field,
      level: field,
      view: field,
      mode: field,
      overlay: field,
      on: field,
      tool: field,
      vertex: field,
      t: field,
    },
    { requiredKeys: ['subdivlab'] },
  ),
);

describe('postMessage commands', () => {
  it('any message is a command that checks again as itself, or refused with a reason that names the command', () => {
    fc.assert(
      fc.property(messages, (data) => {
        const checked = checkCommand(data);
        if (checked.ok) {
          expect(COMMANDS).toContain(checked.command.subdivlab);
          expect(checkCommand(checked.command)).toEqual(checked);
          return;
        }
        expect(checked.reason).toMatch(
          /^(a command is an object|unknown command |(load|set-scheme|set-level|set-view|set-render-mode|set-overlay|set-triangulate|set-tool|set-split)[: ])/,
        );
        // A reason is short enough for a console line, whatever it quotes.
        expect([...checked.reason].length).toBeLessThanOrEqual(200);
      }),
      { numRuns: 1000 },
    );
  });

  it('a cycle, a bigint or a long string in a command is quoted, never thrown (shrunk counterexamples)', () => {
    const cyclic: Record<string, unknown> = {};
    cyclic.self = cyclic;
    expect(checkCommand({ subdivlab: 'set-scheme', scheme: 1n })).toEqual({
      ok: false,
      reason: 'set-scheme: unknown scheme 1n',
    });
    expect(checkCommand({ subdivlab: 'set-render-mode', mode: cyclic })).toEqual({
      ok: false,
      reason: 'set-render-mode: unknown mode an object',
    });
    expect(checkCommand({ subdivlab: cyclic })).toEqual({ ok: false, reason: 'unknown command an object' });
    // Nested 100,000 deep (structured clone carries it): JSON.stringify would overflow the stack.
    let deep: unknown[] = [];
    for (let i = 0; i < 100_000; i++) deep = [deep];
    expect(checkCommand({ subdivlab: 'set-tool', tool: deep })).toEqual({
      ok: false,
      reason: 'set-tool: tool must be none, stencils, basis, split or halfedges, not an array',
    });
    expect(checkCommand({ subdivlab: 'x'.repeat(1 << 20) })).toEqual({
      ok: false,
      reason: `unknown command "${'x'.repeat(79)}…`,
    });
  });

  it('set-split with any t from 0 to 1 reaches the element as that t', () => {
    fc.assert(
      fc.property(fc.double({ min: 0, max: 1, noNaN: true }), (t) => {
        const checked = checkCommand({ subdivlab: 'set-split', t });
        expect(checked.ok).toBe(true);
        if (!checked.ok || checked.command.subdivlab !== 'set-split') return;
        // As iframe-route.ts applies it.
        const element = new Element();
        element.split = checked.command.t;
        expect(element.split).toBe(t + 0);
      }),
      { numRuns: 300 },
    );
  });
});
