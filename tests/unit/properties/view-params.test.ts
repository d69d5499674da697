/**
 * Properties of the viewer's state as text, with fast-check: camera strings
 * (web/render/view-state.ts), link parameters as the app writes and reads
 * them (web/viewer/viewer-params.ts, web/app/url-state.ts's paramsText),
 * line widths (web/render/line-style.ts) and saved views
 * (web/app/saved-views.ts). Bad text is never thrown at anyone: it reads as
 * null, or a value is left out and named in `problems`. Valid state
 * written by the module's own writer reads back.
 */
import fc from 'fast-check';
import './seed';
import { describe, expect, it } from 'vitest';
import { loadViews, parseViews, type SavedView, storeViews } from '../../../web/app/saved-views';
import { paramsText } from '../../../web/app/url-state';
import { MAX_LINE_WIDTH, MIN_LINE_WIDTH, parseLineWidth } from '../../../web/render/line-style';
import { OVERLAY_NAMES, RENDER_MODES } from '../../../web/render/render-mode';
import { checkedView, formatViewString, parseViewString, type ViewState } from '../../../web/render/view-state';
import { PANE_SCHEMES, SCHEME_NAMES } from '../../../web/viewer/scheme-info';
import {
  CONTROLS_MODES,
  MAX_PARAM_LEVELS,
  OVERLAY_KEYS,
  PARAM_KEYS,
  parseViewerParams,
  type ViewerParams,
} from '../../../web/viewer/viewer-params';

type Triple = [number, number, number];

/** Finite coordinates of every size, -0 written as 0 (a camera at -0 is the camera at 0). */
const coordinate = fc
  .oneof(
    fc.double({ noNaN: true, noDefaultInfinity: true }),
    fc.double({ min: -100, max: 100, noNaN: true }),
    fc.integer({ min: -10, max: 10 }),
  )
  .map((x) => x + 0);
const triple: fc.Arbitrary<Triple> = fc.tuple(coordinate, coordinate, coordinate);

/** Views a camera can take: the eye off the target, a non-zero up. Some with the eye very close to the target. */
const views: fc.Arbitrary<ViewState> = fc
  .oneof(
    fc.record({ position: triple, target: triple, up: triple }),
    fc
      .record({
        target: triple,
        offset: fc.tuple(fc.double({ min: -1e-3, max: 1e-3, noNaN: true }), coordinate, coordinate),
        up: triple,
      })
      .map(({ target, offset, up }) => ({
        position: target.map((t, i) => t + offset[i]) as Triple,
        target,
        up,
      })),
  )
  .filter((v) => checkedView(v) !== null);

/** Each number of `b` within 6 significant digits of `a`'s. */
function expectNearViews(b: ViewState, a: ViewState): void {
  const xa = [...a.position, ...a.target, ...a.up];
  const xb = [...b.position, ...b.target, ...b.up];
  xa.forEach((x, i) => {
    expect(Math.abs(xb[i] - x)).toBeLessThanOrEqual(5e-6 * Math.abs(x));
  });
}

/**
 * The app rewrites its hash from the camera it set from the hash: a text of
 * 6-digit numbers is written again as itself. One that needed more digits
 * (the eye within rounding of the target) can round differently the second
 * time (rounding twice), but stays a usable view and is stable from then on.
 */
function expectRewrittenAlike(text: string): void {
  const again = formatViewString(parseViewString(text) as ViewState);
  const sixDigits = text.split(',').every((s) => Number(Number(s).toPrecision(6)) === Number(s));
  if (sixDigits) {
    expect(again).toBe(text);
  } else {
    const view = parseViewString(again);
    expect(view).not.toBeNull();
    expect(formatViewString(view as ViewState)).toBe(again);
  }
}

describe('camera strings', () => {
  it('any text reads as null or as a view a camera can take', () => {
    const numberish = fc.oneof(
      coordinate.map(String),
      fc.constantFrom('', ' ', 'NaN', 'Infinity', '-0', '1e999', '0x10', '1,', 'a'),
      fc.string({ maxLength: 6 }),
    );
    fc.assert(
      fc.property(
        fc.oneof(
          fc.string({ unit: 'binary' }),
          fc.array(numberish, { minLength: 8, maxLength: 10 }).map((p) => p.join(',')),
        ),
        (text) => {
          const view = parseViewString(text);
          if (view !== null) expect(checkedView(view)).toEqual(view);
        },
      ),
      { numRuns: 300 },
    );
  });

  it('a view a camera can take is written and read back, to 6 significant digits', () => {
    fc.assert(
      fc.property(views, (view) => {
        const text = formatViewString(view);
        const back = parseViewString(text);
        expect(back, text).not.toBeNull();
        if (back === null) return;
        expectNearViews(back, view);
        expectRewrittenAlike(text);
      }),
      { numRuns: 500 },
    );
  });
});

/** Link parameters as the app and the snippets write them. */
const validParams: fc.Arbitrary<ViewerParams> = fc
  .record(
    {
      src: fc.string({ unit: 'grapheme', minLength: 1 }),
      scheme: fc.constantFrom(...SCHEME_NAMES),
      levels: fc.integer({ min: 0, max: MAX_PARAM_LEVELS }),
      renderMode: fc.constantFrom(...RENDER_MODES.map((m) => m.mode)),
      overlays: fc.record(
        Object.fromEntries(OVERLAY_NAMES.map((name) => [name, fc.boolean()])) as Record<
          (typeof OVERLAY_NAMES)[number],
          fc.Arbitrary<boolean>
        >,
        { requiredKeys: [] },
      ),
      triangulate: fc.constant(true),
      view: views,
      rules: fc.string({ unit: 'grapheme', minLength: 1 }),
      controls: fc.constantFrom(...CONTROLS_MODES),
      beside: fc.uniqueArray(fc.constantFrom(...PANE_SCHEMES), { minLength: 1, maxLength: 3 }),
      lineWidth: fc.oneof(
        fc.double({ min: MIN_LINE_WIDTH, max: MAX_LINE_WIDTH, noNaN: true }),
        fc.constantFrom(0.5, 1, 1.5, 2, 3, 4),
      ),
    },
    { requiredKeys: [] },
  )
  .map((p) => {
    const out = { ...p } as ViewerParams;
    if (out.overlays && Object.keys(out.overlays).length === 0) delete out.overlays;
    return out;
  });

describe('link parameters', () => {
  it('parameters written as the app writes its hash read back the same (the camera to 6 digits)', () => {
    fc.assert(
      fc.property(validParams, fc.constantFrom('', '#', '?'), (params, lead) => {
        const text = paramsText(params);
        const { params: back, problems } = parseViewerParams(`${lead}${text}`);
        expect(problems).toEqual([]);
        const { view, ...rest } = back;
        const { view: wanted, ...wantedRest } = params;
        expect(rest).toEqual(wantedRest);
        expect(view === undefined).toBe(wanted === undefined);
        if (view && wanted) {
          expect(view).toEqual(parseViewString(formatViewString(wanted)));
          expectNearViews(view, wanted);
        }
        // Read as a URLSearchParams (the iframe route's query) it is the same.
        expect(parseViewerParams(new URLSearchParams(text)).params).toEqual(back);
      }),
      { numRuns: 300 },
    );
  });

  /** Keys whose value is either taken or named in a problem. */
  const CHECKED: [string, RegExp][] = [
    [PARAM_KEYS.scheme, /^Unknown scheme "/],
    [PARAM_KEYS.levels, /^levels must be a whole number from 0 to 8, not "/],
    [PARAM_KEYS.renderMode, /^Unknown render mode "/],
    [PARAM_KEYS.triangulate, /^triangulate must be 1 or 0, not "/],
    [PARAM_KEYS.view, /^view must be nine numbers: camera position, target and up\.$/],
    [PARAM_KEYS.controls, /^controls must be none, minimal or full, not "/],
    [PARAM_KEYS.beside, /^beside takes /],
    [PARAM_KEYS.lineWidth, /^lines must be a width from 0.25 to 8 pixels, not "/],
    ...Object.values(OVERLAY_KEYS).map((key): [string, RegExp] => [key, new RegExp(`^${key} must be 1 or 0, not "`)]),
  ];

  it('any query: each checked value is taken or named in a problem, never both, never neither; nothing throws', () => {
    const value = fc.oneof(
      fc.string({ unit: 'binary', maxLength: 12 }),
      fc.constantFrom(
        '',
        '0',
        '1',
        'on',
        'off',
        ' 3 ',
        '9',
        'loop',
        'smooth',
        'full',
        'loop,sqrt3',
        '0,0,5,0,0,0,0,1,0',
        '0.1',
      ),
    );
    const keys = fc.constantFrom(...CHECKED.map(([key]) => key), PARAM_KEYS.src, PARAM_KEYS.rules, 'other', '');
    fc.assert(
      fc.property(
        fc.array(fc.tuple(keys, value), { maxLength: 14 }),
        fc.string({ unit: 'binary', maxLength: 30 }),
        (pairs, noise) => {
          const query = new URLSearchParams(pairs);
          const text = `${query.toString()}&${noise}`;
          const read = new URLSearchParams(text);
          const { params, problems } = parseViewerParams(text);
          let named = 0;
          for (const [key, problem] of CHECKED) {
            const given = read.get(key);
            const matching = problems.filter((p) => problem.test(p));
            if (given === null) {
              expect(matching).toEqual([]);
              continue;
            }
            const field = (Object.entries(PARAM_KEYS).find(([, k]) => k === key)?.[0] ??
              Object.entries(OVERLAY_KEYS).find(([, k]) => k === key)?.[0]) as string;
            const taken = field in params || (params.overlays !== undefined && field in params.overlays);
            if (key === PARAM_KEYS.beside && given.split(/[\s,]+/).every((n) => n === '')) {
              // An empty beside is none: documented, nothing to name.
              expect(taken || matching.length > 0).toBe(false);
            } else {
              expect(Number(taken) + matching.length, `${key}=${given}`).toBe(1);
            }
            named += matching.length;
          }
          // Every problem is one of these sentences.
          expect(problems.length).toBe(named);
        },
      ),
      { numRuns: 300 },
    );
  });
});

describe('line widths', () => {
  it('any text or number reads as null or a width in range; a width in range as itself', () => {
    fc.assert(
      fc.property(fc.oneof(fc.string({ unit: 'binary' }), fc.double(), coordinate.map(String)), (value) => {
        const width = parseLineWidth(value);
        if (width !== null) {
          expect(width).toBeGreaterThanOrEqual(MIN_LINE_WIDTH);
          expect(width).toBeLessThanOrEqual(MAX_LINE_WIDTH);
        }
      }),
      { numRuns: 1000 },
    );
    fc.assert(
      fc.property(fc.double({ min: MIN_LINE_WIDTH, max: MAX_LINE_WIDTH, noNaN: true }), (w) => {
        expect(parseLineWidth(w)).toBe(w);
        expect(parseLineWidth(String(w))).toBe(w);
      }),
    );
  });
});

/** localStorage as a Map: getItem, setItem, removeItem as the Storage interface has them. */
function memoryStorage(): Storage {
  const items = new Map<string, string>();
  return {
    get length() {
      return items.size;
    },
    clear: () => items.clear(),
    getItem: (key) => items.get(key) ?? null,
    key: (i) => [...items.keys()][i] ?? null,
    removeItem: (key) => {
      items.delete(key);
    },
    setItem: (key, value) => {
      items.set(key, String(value));
    },
  };
}

describe('saved views', () => {
  it('any stored text reads as at most 12 views with distinct, non-blank names', () => {
    const entry = fc.oneof(
      fc.record({ name: fc.oneof(fc.string(), fc.constant(' ')), view: fc.oneof(views, fc.jsonValue()) }),
      fc.jsonValue(),
    );
    fc.assert(
      fc.property(
        fc.oneof(
          fc.string({ unit: 'binary' }),
          fc.json(),
          fc.array(entry, { maxLength: 20 }).map((e) => JSON.stringify(e)),
        ),
        (text) => {
          const read = parseViews(text);
          expect(read.length).toBeLessThanOrEqual(12);
          expect(new Set(read.map((v) => v.name)).size).toBe(read.length);
          for (const { name, view } of read) {
            expect(name.trim()).not.toBe('');
            expect(checkedView(view)).toEqual(view);
          }
        },
      ),
      { numRuns: 500 },
    );
  });

  it('views stored are loaded back as they were', () => {
    const list = fc.uniqueArray(
      fc.record({ name: fc.string({ minLength: 1 }).filter((n) => n.trim() !== ''), view: views }),
      {
        maxLength: 12,
        selector: (v) => v.name,
      },
    );
    fc.assert(
      fc.property(list, (saved: SavedView[]) => {
        const storage = memoryStorage();
        storeViews(saved, storage);
        expect(loadViews(storage)).toEqual(saved);
      }),
      { numRuns: 300 },
    );
  });
});
