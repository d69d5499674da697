/**
 * Client (viewport) coordinates ↔ an element's own CSS pixels, under any
 * CSS transform (scale, translate, rotation, skew) and CSS `zoom` of the
 * element or its ancestors: a viewer on a reveal.js slide, which the deck
 * scales with `transform: scale(…)`, is clicked, dragged and fitted in
 * the same pixels as on a plain page.
 *
 * The browser works the map out: three zero-size probes sit in the
 * element's corners (top left, top right, bottom left), and their client
 * positions (getBoundingClientRect, which applies every transform and
 * zoom above them) give the affine map from the element's box to the
 * viewport. The usual shortcuts are wrong somewhere: `clientX − rect.left`
 * under any scale; the bounding rectangle's ratio to the layout size under
 * a rotation (the rectangle is the rotated box's bounds); MouseEvent
 * offsetX under CSS `zoom` (Chromium 156 gives it in zoomed pixels), and
 * it maps only events, not points back to the screen. A perspective
 * (3D) transform is not affine: under one the map is only the affine map
 * through the three corners, near but not exact away from them.
 */

/** A point: x from the left, y from the top. */
export interface Point {
  x: number;
  y: number;
}

/** A rectangle by its edges. */
export interface Edges {
  left: number;
  top: number;
  right: number;
  bottom: number;
}

const PROBE_CSS =
  'position:absolute;width:0;height:0;padding:0;border:0;margin:0;visibility:hidden;pointer-events:none';

export class ClientMapping {
  /** The probes at the element's top left, top right and bottom left (its padding box). */
  private readonly probes: HTMLElement[];

  /**
   * `element` has no padding (a static one is made `position: relative`,
   * the probes' context); its own pixels are those of {@link size}.
   */
  constructor(private readonly element: HTMLElement) {
    this.probes = ['left:0;top:0', 'left:100%;top:0', 'left:0;top:100%'].map((at) => {
      const probe = document.createElement('span');
      probe.setAttribute('aria-hidden', 'true');
      probe.dataset.clientProbe = '';
      probe.style.cssText = `${PROBE_CSS};${at}`;
      return probe;
    });
  }

  /** The element's size in its own CSS pixels (what the view draws and picks in). */
  get size(): { width: number; height: number } {
    return { width: Math.max(1, this.element.clientWidth), height: Math.max(1, this.element.clientHeight) };
  }

  /** Where the point `local` of the element (its own CSS pixels from its top left) is in the viewport. */
  toClient(local: Point): Point {
    const { origin, ex, ey } = this.frame();
    const { width, height } = this.size;
    const u = local.x / width;
    const v = local.y / height;
    return { x: origin.x + u * ex.x + v * ey.x, y: origin.y + u * ex.y + v * ey.y };
  }

  /** The element's point (its own CSS pixels from its top left) drawn at `client` in the viewport. */
  toLocal(client: Point): Point {
    const { origin, ex, ey } = this.frame();
    const { width, height } = this.size;
    const dx = client.x - origin.x;
    const dy = client.y - origin.y;
    const det = ex.x * ey.y - ex.y * ey.x;
    // Not laid out (display: none, or a zero scale): nothing is drawn to be hit; say where the origin is.
    if (Math.abs(det) < 1e-9) return { x: dx, y: dy };
    const u = (dx * ey.y - dy * ey.x) / det;
    const v = (ex.x * dy - ex.y * dx) / det;
    return { x: u * width, y: v * height };
  }

  /**
   * The box of `descendant` (e.g. a panel over a view) in the element's own
   * pixels: its bounding rectangle's centre mapped back, and its layout
   * size (offsetWidth × offsetHeight, as its own transforms leave it), so a
   * rotated slide does not widen it to its bounds.
   */
  boxOf(descendant: HTMLElement): Edges {
    const r = descendant.getBoundingClientRect();
    const c = this.toLocal({ x: (r.left + r.right) / 2, y: (r.top + r.bottom) / 2 });
    const w = descendant.offsetWidth / 2;
    const h = descendant.offsetHeight / 2;
    return { left: c.x - w, top: c.y - h, right: c.x + w, bottom: c.y + h };
  }

  /** Takes the probes out of the element. */
  dispose(): void {
    for (const probe of this.probes) probe.remove();
  }

  /** The client positions of the element's top left (`origin`) and its top and left edges (`ex`, `ey`, vectors). */
  private frame(): { origin: Point; ex: Point; ey: Point } {
    // Placed first here (and put back if a page or a panel emptied the element), in its box.
    if (this.probes.some((probe) => probe.parentNode !== this.element)) {
      this.element.append(...this.probes);
      if (getComputedStyle(this.element).position === 'static') this.element.style.position = 'relative';
    }
    const [o, x, y] = this.probes.map((p) => p.getBoundingClientRect());
    return {
      origin: { x: o.left, y: o.top },
      ex: { x: x.left - o.left, y: x.top - o.top },
      ey: { x: y.left - o.left, y: y.top - o.top },
    };
  }
}
