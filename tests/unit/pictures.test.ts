/**
 * Fit and the canonical views (web/render/fit.ts), the line widths and the
 * edges' fading (line-style.ts), the saved views (app/saved-views.ts), what
 * Cancel says (app/cancel-message.ts) and the `lines` link value.
 */
import { PerspectiveCamera, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { cancelMessage } from '../../web/app/cancel-message';
import {
  addView,
  LEGACY_VIEW_KEY,
  loadViews,
  parseViews,
  removeView,
  storeViews,
  VIEWS_STORAGE_KEY,
} from '../../web/app/saved-views';
import {
  CANONICAL_VIEWS,
  FIT_FILL,
  fitCamera,
  freeRect,
  nextCanonicalView,
  projectPoints,
  viewOffsetPixels,
} from '../../web/render/fit';
import { edgeOpacity, lineWidthPx, meanSegmentLength, parseLineWidth } from '../../web/render/line-style';
import type { ViewState } from '../../web/render/view-state';
import { formatViewerParams, parseViewerParams } from '../../web/viewer/viewer-params';

/** The eight corners of the box [-1, 1]³ plus an offset. */
const cube = (dx = 0, dy = 0, dz = 0) => {
  const out: number[] = [];
  for (const x of [-1, 1]) for (const y of [-1, 1]) for (const z of [-1, 1]) out.push(x + dx, y + dy, z + dz);
  return out;
};

/** The camera the fit describes, at `aspect`, and the points in NDC. */
function ndcOf(points: number[], fit: NonNullable<ReturnType<typeof fitCamera>>, aspect: number) {
  const camera = new PerspectiveCamera(35, aspect, 0.01, 100);
  const [w, h] = [1000 * aspect, 1000];
  const [x, y] = viewOffsetPixels(fit.offset, w, h);
  camera.setViewOffset(w, h, x, y, w, h);
  camera.position.copy(fit.position);
  camera.up.copy(fit.up);
  camera.lookAt(fit.target);
  camera.updateMatrixWorld();
  const out: Vector3[] = [];
  for (let i = 0; i < points.length; i += 3)
    out.push(new Vector3(points[i], points[i + 1], points[i + 2]).project(camera));
  return out;
}

describe('fitCamera', () => {
  it('frames a cube from the front at the distance worked out by hand', () => {
    const fit = fitCamera({
      points: [cube(2, 0, 0)],
      direction: new Vector3(0, 0, 1),
      up: new Vector3(0, 1, 0),
      fov: 35,
      aspect: 1.6,
    });
    expect(fit).not.toBeNull();
    if (!fit) return;
    // Wider than tall: the vertical limit binds, at the front face (z = 1, y = ±1).
    const ty = Math.tan((17.5 * Math.PI) / 180);
    expect(fit.target.toArray()).toEqual([2, 0, 0]);
    expect(fit.position.z).toBeCloseTo(1 + 1 / (FIT_FILL * ty), 12);
    const ndc = ndcOf(cube(2, 0, 0), fit, 1.6);
    expect(Math.max(...ndc.map((p) => Math.abs(p.y)))).toBeCloseTo(FIT_FILL, 9);
    expect(Math.max(...ndc.map((p) => Math.abs(p.x)))).toBeLessThan(FIT_FILL);
  });

  it('keeps every point of two sets (level and cage) inside a tall view, from any direction', () => {
    const level = cube().map((x) => x * 0.6);
    const cage = cube();
    for (const direction of [new Vector3(0.55, 0.45, 1), new Vector3(-1, 2, 0.3), new Vector3(0, 1, 0)]) {
      const fit = fitCamera({ points: [level, cage], direction, up: new Vector3(0, 1, 0), fov: 35, aspect: 390 / 700 });
      if (!fit) throw new Error('no fit');
      const ndc = ndcOf(cage, fit, 390 / 700);
      const widest = Math.max(...ndc.map((p) => Math.max(Math.abs(p.x), Math.abs(p.y))));
      // Inside, and touching the margin on one side: as close as the canvas allows.
      expect(widest).toBeCloseTo(FIT_FILL, 9);
      expect(fit.position.clone().sub(fit.target).normalize().dot(direction.clone().normalize())).toBeCloseTo(1, 12);
    }
  });

  it('frames points far from the origin as tightly (the fit measures from the box centre in one pass)', () => {
    const far = cube(1e4, -2e4, 5e3).map((x, i) => x + 0.3 * Math.sin(i));
    const free = { x0: 0.3, y0: 0.1, x1: 1, y1: 0.9 };
    const fit = fitCamera({
      points: [far],
      direction: new Vector3(-0.4, 1, 0.7),
      up: new Vector3(0, 1, 0),
      fov: 35,
      aspect: 1.4,
      free,
    });
    if (!fit) throw new Error('no fit');
    const ndc = ndcOf(far, fit, 1.4);
    const [cx, hx, hy] = [0.3, 0.7 * FIT_FILL, 0.8 * FIT_FILL];
    // Inside the free rectangle, touching its margin on one side.
    const widest = Math.max(...ndc.map((p) => Math.max(Math.abs(p.x - cx) / hx, Math.abs(p.y) / hy)));
    expect(widest).toBeCloseTo(1, 6);
  });

  it('puts the model in the free part of the canvas', () => {
    const free = { x0: 0.25, y0: 0, x1: 1, y1: 1 };
    const fit = fitCamera({
      points: [cube()],
      direction: new Vector3(1, 1, 1),
      up: new Vector3(0, 1, 0),
      fov: 35,
      aspect: 1.6,
      free,
    });
    if (!fit) throw new Error('no fit');
    const ndc = ndcOf(cube(), fit, 1.6);
    // Free x from 0.25 to 1 of the width: NDC −0.5 … 1, centre 0.25, half-width 0.75 × 0.9.
    for (const p of ndc) {
      expect(p.x).toBeGreaterThanOrEqual(0.25 - 0.75 * FIT_FILL - 1e-9);
      expect(p.x).toBeLessThanOrEqual(0.25 + 0.75 * FIT_FILL + 1e-9);
      expect(Math.abs(p.y)).toBeLessThanOrEqual(FIT_FILL + 1e-9);
    }
    // The camera looks at the box's centre (the trackball turns about it); the projection is shifted.
    expect(fit.target.toArray()).toEqual([0, 0, 0]);
    expect(fit.offset).toEqual([0.25, 0]);
    expect(Math.max(...ndc.map((p) => Math.abs(p.x - 0.25) / 0.75), ...ndc.map((p) => Math.abs(p.y)))).toBeCloseTo(
      FIT_FILL,
      9,
    );
  });

  it('returns null for no points, and the canonical views look along their axes', () => {
    expect(
      fitCamera({ points: [[]], direction: new Vector3(0, 0, 1), up: new Vector3(0, 1, 0), fov: 35, aspect: 1 }),
    ).toBeNull();
    for (const view of CANONICAL_VIEWS) {
      const fit = fitCamera({
        points: [cube()],
        direction: new Vector3(...view.direction),
        up: new Vector3(...view.up),
        fov: 35,
        aspect: 1,
      });
      if (!fit) throw new Error('no fit');
      const along = fit.position.clone().sub(fit.target).normalize();
      const axis = new Vector3(...view.direction).normalize();
      expect(along.distanceTo(axis)).toBeLessThan(1e-12);
    }
    expect(nextCanonicalView(null)).toBe('front');
    expect(nextCanonicalView('front')).toBe('top');
    expect(nextCanonicalView('iso')).toBe('front');
  });

  it('projects points to CSS pixels without clipping', () => {
    const camera = new PerspectiveCamera(90, 2, 0.1, 10);
    camera.position.set(0, 0, 1);
    camera.lookAt(0, 0, 0);
    // At distance 1 with a 90° vertical field, y = ±1 is the top and bottom edge; x = ±2 the sides.
    expect(projectPoints([0, 0, 0, 2, 1, 0, -4, 0, 0], camera, 200, 100)).toEqual(
      [
        { x: 100, y: 50 },
        { x: 200, y: 0 },
        { x: -100, y: 50 },
      ].map(({ x, y }) => ({ x: expect.closeTo(x, 9), y: expect.closeTo(y, 9) })),
    );
  });
});

describe('freeRect', () => {
  it('cuts the side that leaves more of the canvas', () => {
    // A facts panel 300 × 200 at the top left of 1280 × 800: cutting the left leaves 980 × 800, the top 1280 × 600.
    expect(freeRect(1280, 800, [{ left: 8, top: 8, right: 308, bottom: 208 }])).toEqual({
      x0: 308 / 1280,
      y0: 0,
      x1: 1,
      y1: 1,
    });
    // A folded panel, one line across the top of a phone: the top.
    expect(freeRect(390, 700, [{ left: 8, top: 8, right: 240, bottom: 36 }])).toEqual({
      x0: 0,
      y0: 36 / 700,
      x1: 1,
      y1: 1,
    });
    // A panel covering most of the view is left to fold itself.
    expect(freeRect(400, 400, [{ left: 0, top: 0, right: 300, bottom: 300 }])).toEqual({ x0: 0, y0: 0, x1: 1, y1: 1 });
  });
});

describe('line style', () => {
  it('scales widths with the setting and the picture', () => {
    expect(lineWidthPx('edges', 1, 4)).toBe(4);
    expect(lineWidthPx('control', 2, 1)).toBe(3);
    expect(lineWidthPx('creases', 1, 2)).toBe(8);
    expect(parseLineWidth('1.5')).toBe(1.5);
    expect(parseLineWidth('0')).toBeNull();
    expect(parseLineWidth('wide')).toBeNull();
    expect(parseLineWidth('')).toBeNull();
  });

  it('fades edges by their spacing in line widths', () => {
    expect(edgeOpacity(400, 1)).toBe(1);
    expect(edgeOpacity(60, 1)).toBe(1);
    expect(edgeOpacity(15, 1)).toBeCloseTo(0.5, 12);
    expect(edgeOpacity(6, 1)).toBeCloseTo(Math.sqrt(0.1), 12);
    expect(edgeOpacity(1, 1)).toBe(0.2);
    // ×4 picture: lengths and widths ×4, the same opacity; wider lines fade sooner.
    expect(edgeOpacity(60, 4)).toBeCloseTo(edgeOpacity(15, 1), 12);
    expect(edgeOpacity(20, 2)).toBeLessThan(edgeOpacity(20, 1));
  });

  it('measures the mean edge length', () => {
    // A unit square's four edges and one diagonal: (4 + √2) / 5.
    const square = [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0];
    expect(meanSegmentLength(square, [0, 1, 1, 2, 2, 3, 3, 0, 0, 2])).toBeCloseTo((4 + Math.SQRT2) / 5, 12);
    expect(meanSegmentLength(square, [])).toBe(0);
  });
});

class MemoryStorage implements Storage {
  private readonly items = new Map<string, string>();
  get length() {
    return this.items.size;
  }
  clear() {
    this.items.clear();
  }
  getItem(key: string) {
    return this.items.get(key) ?? null;
  }
  key(i: number) {
    return [...this.items.keys()][i] ?? null;
  }
  removeItem(key: string) {
    this.items.delete(key);
  }
  setItem(key: string, value: string) {
    this.items.set(key, value);
  }
}

const view = (z: number): ViewState => ({ position: [0, 0, z], target: [0, 0, 0], up: [0, 1, 0] });

describe('saved views', () => {
  it('names views by the smallest free number and removes by name', () => {
    let views = addView(addView([], view(1)), view(2));
    expect(views.map((v) => v.name)).toEqual(['View 1', 'View 2']);
    views = removeView(views, 'View 1');
    views = addView(views, view(3));
    expect(views.map((v) => v.name)).toEqual(['View 2', 'View 1']);
    expect(views[1].view).toEqual(view(3));
  });

  it('reads the older single view, stores it back, and skips bad entries', () => {
    const storage = new MemoryStorage();
    storage.setItem(LEGACY_VIEW_KEY, JSON.stringify(view(9)));
    const views = loadViews(storage);
    expect(views).toEqual([{ name: 'View 1', view: view(9) }]);
    storeViews(addView(views, view(5)), storage);
    expect(JSON.parse(storage.getItem(LEGACY_VIEW_KEY) ?? '')).toEqual(view(5));
    expect(loadViews(storage).map((v) => v.view.position[2])).toEqual([9, 5]);
    // An older page saved over the key: its view joins the list.
    storage.setItem(LEGACY_VIEW_KEY, JSON.stringify(view(7)));
    expect(loadViews(storage).map((v) => v.name)).toEqual(['View 1', 'View 2', 'View 3']);
    storeViews([], storage);
    expect(storage.getItem(LEGACY_VIEW_KEY)).toBeNull();
    expect(
      parseViews('[{"name":"a","view":{"position":[0,0,0],"target":[0,0,0],"up":[0,1,0]}},{"name":"b"},3]'),
    ).toEqual([]);
    expect(parseViews('not json')).toEqual([]);
    expect(storage.getItem(VIEWS_STORAGE_KEY)).toBe('[]');
  });
});

describe('cancelMessage', () => {
  it('names the level not computed and the level shown', () => {
    const since = 0;
    expect(cancelMessage({ kind: 'subdivide', label: 'Subdividing to level 3…', level: 3, since }, 2)).toBe(
      'Cancelled: level 3 was not computed; level 2 is shown.',
    );
    expect(cancelMessage({ kind: 'load', label: 'Loading bunny.off…', since }, null)).toBe(
      'Cancelled: bunny.off was not loaded; no model is shown.',
    );
    expect(cancelMessage({ kind: 'load', label: 'Loading bunny.off…', since }, 1)).toBe(
      'Cancelled: bunny.off was not loaded; the previous model is shown.',
    );
    expect(cancelMessage({ kind: 'compute', label: 'Computing stencils…', since }, 1)).toBe(
      'Cancelled: computing stencils stopped; level 1 is shown.',
    );
    expect(cancelMessage(null, 1)).toBeNull();
  });
});

describe('the lines link value', () => {
  it('reads and writes a line width, refuses a bad one', () => {
    expect(parseViewerParams('lines=2').params.lineWidth).toBe(2);
    expect(parseViewerParams('lines=0').problems).toEqual(['lines must be a width from 0.25 to 8 pixels, not "0".']);
    expect(formatViewerParams({ lineWidth: 1.5 }).toString()).toBe('lines=1.5');
  });
});
