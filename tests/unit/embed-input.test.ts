/**
 * What a page can hand an embedded viewer: the element's attributes
 * (web/embed/embed-state.ts) and the iframe route's postMessage commands
 * (web/embed/embed-messages.ts). Bad input is named, never guessed or run.
 */
import { describe, expect, it } from 'vitest';
import { checkCommand } from '../../web/embed/embed-messages';
import { readEmbedState } from '../../web/embed/embed-state';

const attrs = (values: Record<string, string>) => (name: string) => values[name] ?? null;

describe('element attributes', () => {
  it('default to Catmull-Clark level 0, smooth, minimal controls, no overlays but the creases', () => {
    expect(readEmbedState(attrs({}))).toEqual({
      src: '',
      scheme: 'catmull-clark',
      levels: 0,
      renderMode: 'smooth',
      overlays: { control: false, curves: false, bbox: false, creases: true },
      triangulate: false,
      rules: '',
      view: null,
      controls: 'minimal',
      alt: '',
      background: null,
      tool: 'none',
      vertex: null,
      split: 1,
      beside: [],
      distance: true,
      lineWidth: 1,
      problems: [],
    });
  });

  it('read line-width, and name a bad one', () => {
    expect(readEmbedState(attrs({ 'line-width': '2.5' })).lineWidth).toBe(2.5);
    const bad = readEmbedState(attrs({ 'line-width': '20' }));
    expect(bad.lineWidth).toBe(1);
    expect(bad.problems).toEqual([
      { attribute: 'line-width', message: 'line-width must be a width from 0.25 to 8 pixels, not "20".' },
    ]);
  });

  it('read every attribute; a bare boolean attribute is on', () => {
    const state = readEmbedState(
      attrs({
        src: ' meshes/torus.off ',
        scheme: 'loop',
        levels: '3',
        'render-mode': 'edges',
        'control-mesh': '',
        'control-edges': 'true',
        bbox: '0',
        creases: '0',
        triangulate: '',
        rules: 'rules/loop.json',
        view: '1,2,3,0,0,0,0,1,0',
        controls: 'full',
        alt: 'A torus',
        background: 'transparent',
      }),
    );
    expect(state).toMatchObject({
      src: 'meshes/torus.off',
      scheme: 'loop',
      levels: 3,
      renderMode: 'edges',
      overlays: { control: true, curves: true, bbox: false, creases: false },
      triangulate: true,
      rules: 'rules/loop.json',
      view: { position: [1, 2, 3], target: [0, 0, 0], up: [0, 1, 0] },
      controls: 'full',
      alt: 'A torus',
      background: 'transparent',
      problems: [],
    });
  });

  it('fall back to the default for a bad value and name the attribute', () => {
    const state = readEmbedState(
      attrs({ scheme: 'butterfly', levels: 'two', 'render-mode': 'x', view: '1,2', controls: 'all', bbox: 'maybe' }),
    );
    expect(state).toMatchObject({
      scheme: 'catmull-clark',
      levels: 0,
      renderMode: 'smooth',
      view: null,
      controls: 'minimal',
    });
    expect(state.problems.map((p) => p.attribute)).toEqual([
      'scheme',
      'levels',
      'render-mode',
      'view',
      'controls',
      'bbox',
    ]);
    expect(state.problems[1].message).toBe('levels must be a whole number from 0 to 8, not "two".');
  });
});

describe('teaching tool attributes', () => {
  it('read tool, vertex and split', () => {
    expect(readEmbedState(attrs({ tool: 'stencils', vertex: '7' }))).toMatchObject({
      tool: 'stencils',
      vertex: 7,
      split: 1,
      problems: [],
    });
    expect(readEmbedState(attrs({ tool: 'basis', vertex: ' 0 ' }))).toMatchObject({ tool: 'basis', vertex: 0 });
    for (const [text, t] of [
      ['0', 0],
      ['0.5', 0.5],
      ['.25', 0.25],
      ['1', 1],
      ['1.0', 1],
    ] as const) {
      expect(readEmbedState(attrs({ tool: 'split', split: text }))).toMatchObject({
        tool: 'split',
        split: t,
        problems: [],
      });
    }
    // Present but empty: as if absent.
    expect(readEmbedState(attrs({ tool: '', vertex: '', split: '' }))).toMatchObject({
      tool: 'none',
      vertex: null,
      split: 1,
      problems: [],
    });
  });

  it.each([
    ['tool', 'stencil', 'tool must be none, stencils, basis, split or halfedges, not "stencil".'],
    ['tool', 'Basis', 'tool must be none, stencils, basis, split or halfedges, not "Basis".'],
    ['vertex', '-1', 'vertex must be a whole number ≥ 0, not "-1".'],
    ['vertex', '2.5', 'vertex must be a whole number ≥ 0, not "2.5".'],
    ['vertex', 'seven', 'vertex must be a whole number ≥ 0, not "seven".'],
    ['vertex', '1e3', 'vertex must be a whole number ≥ 0, not "1e3".'],
    ['vertex', '99999999999999999999', 'vertex must be a whole number ≥ 0, not "99999999999999999999".'],
    ['split', '1.5', 'split must be a number from 0 to 1, not "1.5".'],
    ['split', '-0.1', 'split must be a number from 0 to 1, not "-0.1".'],
    ['split', 'half', 'split must be a number from 0 to 1, not "half".'],
    ['split', 'NaN', 'split must be a number from 0 to 1, not "NaN".'],
    ['split', '0x1', 'split must be a number from 0 to 1, not "0x1".'],
  ])('name a bad %s="%s" and use the default', (attribute, value, message) => {
    const state = readEmbedState(attrs({ tool: 'split', [attribute]: value }));
    expect(state.problems).toEqual([{ attribute, message }]);
    expect(state).toMatchObject({
      tool: attribute === 'tool' ? 'none' : 'split',
      vertex: null,
      split: 1,
    });
  });
});

describe('side-by-side attributes', () => {
  it('read beside and distance (on unless 0)', () => {
    expect(readEmbedState(attrs({}))).toMatchObject({ beside: [], distance: true });
    expect(readEmbedState(attrs({ beside: 'loop sqrt3', distance: '0' }))).toMatchObject({
      beside: ['loop', 'sqrt3'],
      distance: false,
      problems: [],
    });
  });

  it('name a bad beside as its problem and show one view', () => {
    const state = readEmbedState(attrs({ beside: 'loop custom' }));
    expect(state.beside).toEqual([]);
    expect(state.problems).toEqual([{ attribute: 'beside', message: expect.stringMatching(/not "custom"\.$/) }]);
    expect(readEmbedState(attrs({ distance: 'maybe' })).problems[0].attribute).toBe('distance');
  });
});

describe('element attributes, together', () => {
  it('name scheme="custom" without rules as a problem of the rules attribute', () => {
    expect(readEmbedState(attrs({ scheme: 'custom' })).problems).toEqual([
      { attribute: 'rules', message: 'scheme="custom" needs a rules attribute: the URL of a rule-set JSON.' },
    ]);
    expect(readEmbedState(attrs({ scheme: 'custom', rules: 'rules/loop.json' })).problems).toEqual([]);
  });
});

describe('iframe commands', () => {
  it('accept the documented commands with their fields', () => {
    expect(checkCommand({ subdivlab: 'load', src: 'meshes/cube.off' })).toEqual({
      ok: true,
      command: { subdivlab: 'load', src: 'meshes/cube.off' },
    });
    expect(checkCommand({ subdivlab: 'load', text: 'OFF\n', name: 'a.off', extra: 1 })).toEqual({
      ok: true,
      command: { subdivlab: 'load', text: 'OFF\n', name: 'a.off' },
    });
    expect(checkCommand({ subdivlab: 'set-scheme', scheme: 'doo-sabin' })).toMatchObject({ ok: true });
    expect(checkCommand({ subdivlab: 'subdivide' })).toEqual({ ok: true, command: { subdivlab: 'subdivide' } });
    expect(checkCommand({ subdivlab: 'set-level', level: 0 })).toMatchObject({ ok: true });
    expect(checkCommand({ subdivlab: 'set-view', view: '1,2,3,0,0,0,0,1,0' })).toEqual({
      ok: true,
      command: { subdivlab: 'set-view', view: { position: [1, 2, 3], target: [0, 0, 0], up: [0, 1, 0] } },
    });
    expect(
      checkCommand({ subdivlab: 'set-view', view: { position: [0, 0, 5], target: [0, 0, 0], up: [0, 1, 0] } }),
    ).toMatchObject({ ok: true });
  });

  it('accept display commands', () => {
    expect(checkCommand({ subdivlab: 'set-render-mode', mode: 'wireframe' })).toEqual({
      ok: true,
      command: { subdivlab: 'set-render-mode', mode: 'wireframe' },
    });
    expect(checkCommand({ subdivlab: 'set-overlay', overlay: 'bbox', on: false })).toEqual({
      ok: true,
      command: { subdivlab: 'set-overlay', overlay: 'bbox', on: false },
    });
    expect(checkCommand({ subdivlab: 'set-triangulate', on: true })).toMatchObject({ ok: true });
  });

  it('accept the teaching tool commands', () => {
    expect(checkCommand({ subdivlab: 'set-tool', tool: 'stencils', vertex: 7 })).toEqual({
      ok: true,
      command: { subdivlab: 'set-tool', tool: 'stencils', vertex: 7 },
    });
    expect(checkCommand({ subdivlab: 'set-tool', tool: 'none', extra: 'x' })).toEqual({
      ok: true,
      command: { subdivlab: 'set-tool', tool: 'none' },
    });
    expect(checkCommand({ subdivlab: 'set-split', t: 0.5 })).toEqual({
      ok: true,
      command: { subdivlab: 'set-split', t: 0.5 },
    });
    expect(checkCommand({ subdivlab: 'set-split', t: 0 })).toMatchObject({ ok: true });
  });

  it.each([
    [{ subdivlab: 'set-render-mode', mode: 'glossy' }, 'set-render-mode: unknown mode "glossy"'],
    [
      { subdivlab: 'set-overlay', overlay: 'src', on: true },
      'set-overlay needs overlay (control-mesh, control-edges, bbox or creases) and on (true or false)',
    ],
    [
      { subdivlab: 'set-overlay', overlay: 'bbox', on: 1 },
      'set-overlay needs overlay (control-mesh, control-edges, bbox or creases) and on (true or false)',
    ],
    [{ subdivlab: 'set-triangulate', on: 'yes' }, 'set-triangulate needs on (true or false)'],
    [null, 'a command is an object { subdivlab: NAME, ... }'],
    ['set-level 2', 'a command is an object { subdivlab: NAME, ... }'],
    [[1, 2], 'a command is an object { subdivlab: NAME, ... }'],
    [{ subdivlab: 'eval', code: '1' }, 'unknown command "eval"'],
    [{ type: 'subdivide' }, 'unknown command undefined'],
    [{ subdivlab: 'load' }, 'load needs src (a URL) or text and name (the mesh file)'],
    [{ subdivlab: 'load', src: 42 }, 'load needs src (a URL) or text and name (the mesh file)'],
    [{ subdivlab: 'set-scheme', scheme: 'toString' }, 'set-scheme: unknown scheme "toString"'],
    [{ subdivlab: 'set-level', level: '2' }, 'set-level needs level, a whole number ≥ 0'],
    [{ subdivlab: 'set-level', level: 1.5 }, 'set-level needs level, a whole number ≥ 0'],
    [{ subdivlab: 'set-level', level: -1 }, 'set-level needs level, a whole number ≥ 0'],
    [{ subdivlab: 'set-level', level: 9 }, 'set-level: at most 8'],
    [{ subdivlab: 'set-view', view: '1,2,3' }, 'set-view needs view: nine numbers, or { position, target, up }'],
    [
      { subdivlab: 'set-view', view: { position: [0, 0, 1] } },
      'set-view needs view: nine numbers, or { position, target, up }',
    ],
    [
      { subdivlab: 'set-tool', tool: 'stencil' },
      'set-tool: tool must be none, stencils, basis, split or halfedges, not "stencil"',
    ],
    [{ subdivlab: 'set-tool' }, 'set-tool: tool must be none, stencils, basis, split or halfedges, not undefined'],
    [{ subdivlab: 'set-tool', tool: 'basis', vertex: -1 }, 'set-tool: vertex must be a whole number ≥ 0'],
    [{ subdivlab: 'set-tool', tool: 'basis', vertex: '3' }, 'set-tool: vertex must be a whole number ≥ 0'],
    [{ subdivlab: 'set-tool', tool: 'basis', vertex: 0.5 }, 'set-tool: vertex must be a whole number ≥ 0'],
    [{ subdivlab: 'set-split', t: 2 }, 'set-split needs t, a number from 0 to 1'],
    [{ subdivlab: 'set-split', t: '0.5' }, 'set-split needs t, a number from 0 to 1'],
    [{ subdivlab: 'set-split', t: Number.NaN }, 'set-split needs t, a number from 0 to 1'],
    [{ subdivlab: 'set-split' }, 'set-split needs t, a number from 0 to 1'],
  ])('refuse %j: %s', (data, reason) => {
    expect(checkCommand(data)).toEqual({ ok: false, reason });
  });
});
