/**
 * The viewer's state as text (web/viewer/viewer-params.ts, view-state.ts):
 * what a share link, an iframe query and the element's attributes carry.
 */
import { describe, expect, it } from 'vitest';
import { formatViewString, parseViewString } from '../../web/render/view-state';
import { formatViewerParams, parseBeside, parseViewerParams } from '../../web/viewer/viewer-params';

describe('view strings', () => {
  it('write nine numbers to six significant digits and read them back', () => {
    const view = {
      position: [2.123456789, -0.000123456789, 3] as [number, number, number],
      target: [0, -0, 1e-9] as [number, number, number],
      up: [0, 1, 0] as [number, number, number],
    };
    const text = formatViewString(view);
    expect(text).toBe('2.12346,-0.000123457,3,0,0,1e-9,0,1,0');
    expect(parseViewString(text)).toEqual({
      position: [2.12346, -0.000123457, 3],
      target: [0, 0, 1e-9],
      up: [0, 1, 0],
    });
  });

  it('refuse anything but nine finite numbers with the eye off the target and a non-zero up', () => {
    for (const bad of [
      '',
      '1,2,3',
      '1,2,3,0,0,0,0,1',
      '1,2,3,0,0,0,0,1,0,5',
      'a,2,3,0,0,0,0,1,0',
      '1,2,,0,0,0,0,1,0',
    ]) {
      expect(parseViewString(bad)).toBeNull();
    }
    expect(parseViewString('1,2,3,4,5,6,0,1,Infinity')).toBeNull();
    expect(parseViewString('1,1,1,1,1,1,0,1,0')).toBeNull();
    expect(parseViewString('1,2,3,0,0,0,0,0,0')).toBeNull();
  });
});

describe('viewer parameters', () => {
  it('read every key of a share link', () => {
    const { params, problems } = parseViewerParams(
      '#src=meshes%2Ftorus.off&scheme=loop&levels=2&mode=edges&control-mesh=1&control-edges=0&bbox=true&view=1,2,3,0,0,0,0,1,0&controls=minimal&rules=rules%2Floop.json&triangulate=1',
    );
    expect(problems).toEqual([]);
    expect(params).toEqual({
      src: 'meshes/torus.off',
      scheme: 'loop',
      levels: 2,
      renderMode: 'edges',
      overlays: { control: true, curves: false, bbox: true },
      triangulate: true,
      view: { position: [1, 2, 3], target: [0, 0, 0], up: [0, 1, 0] },
      controls: 'minimal',
      rules: 'rules/loop.json',
    });
  });

  it('leave out bad values and name each one', () => {
    const { params, problems } = parseViewerParams(
      '?scheme=butterfly&levels=-1&mode=glossy&control-mesh=maybe&view=1,2&controls=some&src=cube.off',
    );
    expect(params).toEqual({ src: 'cube.off' });
    expect(problems).toEqual([
      'Unknown scheme "butterfly".',
      'levels must be a whole number from 0 to 8, not "-1".',
      'Unknown render mode "glossy" (smooth, flat, edges, wireframe, zebra, mean-curvature, gaussian-curvature).',
      'control-mesh must be 1 or 0, not "maybe".',
      'view must be nine numbers: camera position, target and up.',
      'controls must be none, minimal or full, not "some".',
    ]);
    expect(parseViewerParams('levels=9').problems).toEqual(['levels must be a whole number from 0 to 8, not "9".']);
    expect(parseViewerParams('levels=2.5').params.levels).toBeUndefined();
  });

  it('round-trip through text in a fixed key order', () => {
    const params = {
      src: 'https://example.org/a b.off',
      scheme: 'doo-sabin' as const,
      levels: 3,
      renderMode: 'wireframe' as const,
      overlays: { control: true, curves: true, bbox: false },
      triangulate: true,
      view: {
        position: [0.5, 4, -2] as [number, number, number],
        target: [0, 0, 0] as [number, number, number],
        up: [0, 0, 1] as [number, number, number],
      },
      controls: 'none' as const,
    };
    const text = formatViewerParams(params).toString();
    expect(text).toBe(
      'src=https%3A%2F%2Fexample.org%2Fa+b.off&scheme=doo-sabin&levels=3&mode=wireframe&control-mesh=1&bbox=0&control-edges=1&triangulate=1&view=0.5%2C4%2C-2%2C0%2C0%2C0%2C0%2C0%2C1&controls=none',
    );
    expect(parseViewerParams(text)).toEqual({ params, problems: [] });
  });
});

describe('side by side in links (beside)', () => {
  it('reads one to three built-in schemes, by commas or spaces, and writes them with commas', () => {
    expect(parseViewerParams('beside=loop').params.beside).toEqual(['loop']);
    expect(parseViewerParams('beside=loop,sqrt3').params.beside).toEqual(['loop', 'sqrt3']);
    expect(parseViewerParams('beside=loop+sqrt3++doo-sabin').params.beside).toEqual(['loop', 'sqrt3', 'doo-sabin']);
    expect(parseViewerParams('beside=').params.beside).toBeUndefined();
    const text = formatViewerParams({ scheme: 'catmull-clark', beside: ['quad-triangle', 'loop'] }).toString();
    expect(text).toBe('scheme=catmull-clark&beside=quad-triangle%2Cloop');
    expect(parseViewerParams(text).params.beside).toEqual(['quad-triangle', 'loop']);
  });

  it('names an unknown or custom scheme and more than three, and leaves beside out', () => {
    const custom = parseViewerParams('beside=loop,custom');
    expect(custom.params.beside).toBeUndefined();
    expect(custom.problems).toEqual([
      'beside takes the names of schemes with built-in rules (catmull-clark, loop, doo-sabin, sqrt3, quad-triangle, linear, linear-tri), not "custom".',
    ]);
    expect(parseBeside('loop butterfly').problem).toMatch(/not "butterfly"\.$/);
    expect(parseBeside('loop,sqrt3,linear,doo-sabin')).toEqual({
      schemes: [],
      problem: 'beside takes at most 3 schemes, not 4.',
    });
  });
});
