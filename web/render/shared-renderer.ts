/**
 * One WebGL renderer for every view on a page. Browsers keep about 16 WebGL
 * contexts alive and drop the oldest beyond that, so a lecture page with a
 * dozen viewers cannot give each its own. Each view keeps a plain 2D canvas
 * in its own place in the page (so page CSS, stacking and shadow DOM work as
 * for any element); the shared renderer draws the view's scene into the
 * corner of its own canvas and the view copies that corner into its 2D
 * canvas in the same task, before the browser clears the drawing buffer.
 * (three.js's multiple-elements example draws every view into one canvas
 * behind the page instead; that canvas would sit under the page's own
 * backgrounds and above nothing else, which a teacher's page cannot be
 * asked to allow for.)
 */
import { type Camera, Color, type Scene, WebGLRenderer } from 'three';

export class SharedRenderer {
  readonly renderer: WebGLRenderer;
  private width = 1;
  private height = 1;
  private readonly clearColor = new Color();
  private readonly views = new Set<() => void>();

  constructor() {
    this.renderer = new WebGLRenderer({ antialias: true, alpha: true });
    // three.js rebuilds its GPU state when a lost context comes back; the views then draw again.
    this.renderer.domElement.addEventListener('webglcontextrestored', () => {
      for (const redraw of this.views) redraw();
    });
    // Views work in device pixels themselves.
    this.renderer.setPixelRatio(1);
    this.renderer.setSize(this.width, this.height, false);
    this.renderer.setScissorTest(true);
  }

  /** Registers a view's redraw request, called when a lost WebGL context is restored; returns the unregister function. */
  attach(redraw: () => void): () => void {
    this.views.add(redraw);
    return () => this.views.delete(redraw);
  }

  /** Largest picture side the GPU can draw. */
  get maxSize(): number {
    const gl = this.renderer.getContext();
    return Math.min(this.renderer.capabilities.maxTextureSize, gl.getParameter(gl.MAX_RENDERBUFFER_SIZE));
  }

  /**
   * Draws `scene` seen by `camera` into `target` (whose canvas is `width` ×
   * `height` device pixels), on `background` (null: transparent).
   */
  draw(
    scene: Scene,
    camera: Camera,
    target: CanvasRenderingContext2D,
    width: number,
    height: number,
    background: string | null,
  ): void {
    this.reserve(width, height);
    const r = this.renderer;
    r.setViewport(0, 0, width, height);
    r.setScissor(0, 0, width, height);
    r.setClearColor(this.clearColor.set(background ?? '#000000'), background ? 1 : 0);
    r.render(scene, camera);
    // WebGL's origin is the bottom-left corner; the canvas image's is the top-left.
    target.clearRect(0, 0, width, height);
    target.drawImage(r.domElement, 0, this.height - height, width, height, 0, 0, width, height);
  }

  /** Grows the drawing buffer to hold `width` × `height`. */
  private reserve(width: number, height: number): void {
    if (width <= this.width && height <= this.height) return;
    this.width = Math.max(this.width, width);
    this.height = Math.max(this.height, height);
    this.renderer.setSize(this.width, this.height, false);
  }

  /** Gives back a drawing buffer grown for a large export: the next draw sizes it for the views again. */
  shrink(): void {
    if (this.width === 1 && this.height === 1) return;
    this.width = 1;
    this.height = 1;
    this.renderer.setSize(1, 1, false);
  }

  /** Geometries and textures alive on the GPU for the whole page (three's renderer.info). */
  memory(): { geometries: number; textures: number } {
    const { geometries, textures } = this.renderer.info.memory;
    return { geometries, textures };
  }
}

let shared: SharedRenderer | null = null;

/** The page's renderer, made on first use. */
export function sharedRenderer(): SharedRenderer {
  shared ??= new SharedRenderer();
  return shared;
}
