/**
 * three's TrackballControls reading the pointer in the view's own pixels
 * (client-mapping.ts), so that a drag turns the model as far on a scaled,
 * zoomed or rotated slide as on a plain page.
 *
 * TrackballControls measures its element once (handleResize: the bounding
 * rectangle) and reads pointers as page coordinates against it: a slide
 * the deck rescales afterwards (a presenter's full screen) leaves that
 * rectangle stale, and under a rotation it is the rotated box's bounds.
 * Here its "screen" is the element's own box at (0, 0), and its two
 * readers (the same formulas as three 0.187's) take the pointer there
 * first.
 */
import { type Camera, Vector2 } from 'three';
import { TrackballControls } from 'three/addons/controls/TrackballControls.js';
import type { ClientMapping } from './client-mapping';

export class MappedTrackballControls extends TrackballControls {
  private readonly mapped = new Vector2();

  constructor(
    camera: Camera,
    element: HTMLElement,
    private readonly mapping: ClientMapping,
  ) {
    super(camera, element);
    this.handleResize();
  }

  /** The element's own box, from (0, 0): pointers are mapped into it (see {@link _getMouseOnScreen}). */
  override handleResize(): void {
    // Called by the base constructor, before `mapping` is set.
    if (!this.mapping) return;
    const { width, height } = this.mapping.size;
    this.screen = { left: 0, top: 0, width, height };
  }

  /** The pointer at (pageX, pageY) in the view's own pixels. */
  private local(pageX: number, pageY: number): { x: number; y: number } {
    return this.mapping.toLocal({ x: pageX - window.scrollX, y: pageY - window.scrollY });
  }

  /** Overrides TrackballControls' reader: the pointer in fractions of the view, (0, 0) at its top left. */
  _getMouseOnScreen(pageX: number, pageY: number): Vector2 {
    const { x, y } = this.local(pageX, pageY);
    return this.mapped.set(x / this.screen.width, y / this.screen.height);
  }

  /** Overrides TrackballControls' reader: the pointer on its virtual trackball (the width is the unit on both axes, as three has it). */
  _getMouseOnCircle(pageX: number, pageY: number): Vector2 {
    const { x, y } = this.local(pageX, pageY);
    const { width, height } = this.screen;
    return this.mapped.set((x - width * 0.5) / (width * 0.5), (height - 2 * y) / width);
  }
}
