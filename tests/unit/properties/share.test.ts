/**
 * Properties of sharing a view, with fast-check: the app's state as link
 * parameters (web/app/url-state.ts's paramsOfState), written as an element
 * snippet or an iframe snippet (web/app/embed-snippets.ts), must start the
 * embedded viewer in that state: the snippet's attributes, or the iframe's
 * query as the iframe route turns it into attributes
 * (web/embed/embed-state.ts, attributesOfParams), read by readEmbedState.
 */
import fc from 'fast-check';
import './seed';
import { describe, expect, it } from 'vitest';
import { elementSnippet, iframeSnippet } from '../../../web/app/embed-snippets';
import { paramsOfState } from '../../../web/app/url-state';
import { attributesOfParams, type EmbedState, readEmbedState } from '../../../web/embed/embed-state';
import { DEFAULT_LINE_WIDTH, MAX_LINE_WIDTH, MIN_LINE_WIDTH } from '../../../web/render/line-style';
import { OVERLAY_DEFAULTS, OVERLAY_NAMES, RENDER_MODES } from '../../../web/render/render-mode';
import { checkedView, formatViewString, parseViewString, type ViewState } from '../../../web/render/view-state';
import { PANE_SCHEMES, SCHEME_NAMES } from '../../../web/viewer/scheme-info';
import type { ViewerState } from '../../../web/viewer/subdiv-viewer';
import { parseViewerParams, type ViewerParams } from '../../../web/viewer/viewer-params';

const subject = { appBase: 'https://example.org/lab/', modelName: 'cube.off', faces: 24 };

const views: fc.Arbitrary<ViewState> = fc
  .record({
    position: fc.tuple(fc.double({ min: -50, max: 50, noNaN: true }), fc.integer(), fc.integer()),
    target: fc.tuple(fc.integer({ min: -3, max: 3 }), fc.integer({ min: -3, max: 3 }), fc.integer({ min: -3, max: 3 })),
    up: fc.constantFrom<[number, number, number]>([0, 1, 0], [0, 0, 1]),
  })
  .filter((v) => checkedView(v) !== null);

/** Link parameters as the app makes them from its state (paramsOfState), with panes beside. */
const shared: fc.Arbitrary<ViewerParams> = fc
  .record({
    scheme: fc.constantFrom(...SCHEME_NAMES.filter((s) => s !== 'custom')),
    levelCount: fc.integer({ min: 1, max: 6 }),
    level: fc.integer({ min: 0, max: 5 }),
    triangulate: fc.boolean(),
    renderMode: fc.constantFrom(...RENDER_MODES.map((m) => m.mode)),
    overlays: fc.record({ control: fc.boolean(), bbox: fc.boolean(), curves: fc.boolean(), creases: fc.boolean() }),
    lineWidth: fc.oneof(
      fc.constant(DEFAULT_LINE_WIDTH),
      fc.double({ min: MIN_LINE_WIDTH, max: MAX_LINE_WIDTH, noNaN: true }),
    ),
    src: fc.constantFrom('meshes/cube.off', 'https://data.example.org/m.obj?a=1&b="x"'),
    view: views,
    beside: fc.uniqueArray(fc.constantFrom(...PANE_SCHEMES), { maxLength: 3 }),
  })
  .map((s) => {
    const state = { ...s, level: Math.min(s.level, s.levelCount - 1) } as unknown as ViewerState;
    const params = paramsOfState(state, s.src, s.view);
    return s.beside.length > 0 ? { ...params, beside: s.beside } : params;
  });

/** What an element started from `params` must show. */
function expectShows(state: EmbedState, params: ViewerParams): void {
  expect(state.problems).toEqual([]);
  expect(state.scheme).toBe(params.scheme ?? 'catmull-clark');
  expect(state.levels).toBe(params.levels ?? 0);
  expect(state.renderMode).toBe(params.renderMode ?? 'smooth');
  for (const name of OVERLAY_NAMES) {
    expect(state.overlays[name], name).toBe(params.overlays?.[name] ?? OVERLAY_DEFAULTS[name]);
  }
  expect(state.triangulate).toBe(params.triangulate ?? false);
  expect(state.view).toEqual(params.view ? parseViewString(formatViewString(params.view)) : null);
  expect(state.beside).toEqual(params.beside ?? []);
  expect(state.lineWidth).toBe(params.lineWidth ?? DEFAULT_LINE_WIDTH);
  expect(state.src).toBe(params.src ? new URL(params.src, subject.appBase).href : '');
}

/** The attributes of the snippet's element, unescaped as an HTML parser would. */
function snippetAttributes(code: string): Map<string, string> {
  const element = /<subdiv-viewer\n([\s\S]*)\n><\/subdiv-viewer>/.exec(code)?.[1] ?? '';
  const attributes = new Map<string, string>();
  for (const line of element.split('\n')) {
    const m = /^ {2}([a-z-]+)(?:="([^"]*)")?$/.exec(line);
    expect(m, line).not.toBeNull();
    if (!m) continue;
    const value = (m[2] ?? '')
      .replace(/&quot;/g, '"')
      .replace(/&lt;/g, '<')
      .replace(/&gt;/g, '>')
      .replace(/&amp;/g, '&');
    attributes.set(m[1], value);
  }
  return attributes;
}

describe('sharing a view', () => {
  it('the element snippet starts the element in the shared state', () => {
    fc.assert(
      fc.property(shared, (params) => {
        const attributes = snippetAttributes(elementSnippet(params, subject));
        expectShows(
          readEmbedState((name) => attributes.get(name) ?? null),
          params,
        );
      }),
      { numRuns: 150 },
    );
  });

  it('the iframe snippet starts the iframe route in the shared state', () => {
    fc.assert(
      fc.property(shared, (params) => {
        const code = iframeSnippet(params, subject);
        const src = (/src="([^"]*)"/.exec(code)?.[1] ?? '').replace(/&quot;/g, '"').replace(/&amp;/g, '&');
        const query = parseViewerParams(new URL(src).search);
        expect(query.problems).toEqual([]);
        const attributes = new Map(attributesOfParams(query.params));
        expectShows(
          readEmbedState((name) => attributes.get(name) ?? null),
          params,
        );
      }),
      { numRuns: 150 },
    );
  });

  it('creases switched off and a line width reach both snippets (shrunk counterexample)', () => {
    const params: ViewerParams = { scheme: 'loop', levels: 1, overlays: { creases: false }, lineWidth: 2 };
    const attributes = snippetAttributes(elementSnippet(params, subject));
    expect(attributes.get('creases')).toBe('0');
    expect(attributes.get('line-width')).toBe('2');
    expect(attributesOfParams(params)).toEqual([
      ['scheme', 'loop'],
      ['levels', '1'],
      ['creases', '0'],
      ['line-width', '2'],
    ]);
  });
});
