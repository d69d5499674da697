/** The first look (web/app/first-look.ts): which models keep the first visit's edges and cage, and which settings it leaves alone. */
import { describe, expect, it } from 'vitest';
import { FIRST_LOOK_MAX_FACES, FirstLook, type LookTarget, lookFor } from '../../web/app/first-look';
import type { RenderMode } from '../../web/render/render-mode';

/** A viewer's display settings, with a log of what was set. */
function fakeViewer(
  renderMode: RenderMode,
  control: boolean,
): LookTarget & { sets: string[]; state: { renderMode: RenderMode; overlays: { control: boolean } } } {
  const state = { renderMode, overlays: { control } };
  const sets: string[] = [];
  return {
    state,
    sets,
    setRenderMode: (mode) => {
      state.renderMode = mode;
      sets.push(`mode ${mode}`);
    },
    setOverlay: (_name, visible) => {
      state.overlays.control = visible;
      sets.push(`cage ${visible}`);
    },
  };
}

describe('lookFor', () => {
  it('keeps edges and the cage up to 1,000 faces, smooth without the cage above', () => {
    expect(FIRST_LOOK_MAX_FACES).toBe(1000);
    // The rhombicuboctahedron of the first visit (26 faces), a cube at level 4 (1,536 quads), CGAL's elephant.
    expect(lookFor(26)).toEqual({ renderMode: 'edges', control: true });
    expect(lookFor(1000)).toEqual({ renderMode: 'edges', control: true });
    expect(lookFor(1001)).toEqual({ renderMode: 'smooth', control: false });
    expect(lookFor(5558)).toEqual({ renderMode: 'smooth', control: false });
  });
});

describe('FirstLook', () => {
  it('does nothing before the first visit began (a link, ?src=)', () => {
    const viewer = fakeViewer('edges', true);
    new FirstLook().apply(viewer, 5558);
    expect(viewer.sets).toEqual([]);
  });

  it('follows each model while nothing was chosen: scan, cube, scan', () => {
    const viewer = fakeViewer('edges', true);
    const look = new FirstLook();
    look.begin({ renderMode: 'edges', control: true });
    look.apply(viewer, 5558);
    expect(viewer.state).toEqual({ renderMode: 'smooth', overlays: { control: false } });
    look.apply(viewer, 6);
    expect(viewer.state).toEqual({ renderMode: 'edges', overlays: { control: true } });
    look.apply(viewer, 1001);
    expect(viewer.sets).toEqual(['mode smooth', 'cage false', 'mode edges', 'cage true', 'mode smooth', 'cage false']);
  });

  it('leaves a chosen cage, and a cage a tool turned on, while the mode still follows', () => {
    const viewer = fakeViewer('edges', true);
    const look = new FirstLook();
    look.begin({ renderMode: 'edges', control: true });
    look.chose('control');
    look.apply(viewer, 5558);
    expect(viewer.state).toEqual({ renderMode: 'smooth', overlays: { control: true } });

    const other = fakeViewer('edges', true);
    const look2 = new FirstLook();
    look2.begin({ renderMode: 'edges', control: true });
    look2.apply(other, 5558);
    // A tool (Edit creases, the basis view) turned the cage on since: it stays, now and later.
    other.state.overlays.control = true;
    look2.apply(other, 5558);
    look2.apply(other, 6);
    look2.apply(other, 5558);
    expect(other.state.overlays.control).toBe(true);
    expect(other.state.renderMode).toBe('smooth');
  });

  it('leaves everything after a link or a chosen mode', () => {
    const viewer = fakeViewer('edges', true);
    const look = new FirstLook();
    look.begin({ renderMode: 'edges', control: true });
    look.chose('renderMode');
    look.apply(viewer, 5558);
    expect(viewer.state).toEqual({ renderMode: 'edges', overlays: { control: false } });
    look.end();
    look.apply(viewer, 6);
    expect(viewer.state).toEqual({ renderMode: 'edges', overlays: { control: false } });
  });
});
