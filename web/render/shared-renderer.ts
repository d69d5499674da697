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
import {
  type BufferAttribute,
  BufferGeometry,
  type Camera,
  Color,
  type InterleavedBufferAttribute,
  Mesh,
  MeshBasicMaterial,
  OrthographicCamera,
  Scene,
  Sphere,
  WebGLRenderer,
} from 'three';
import { PartedAttribute } from './parted-attribute';

type Attribute = BufferAttribute | InterleavedBufferAttribute;

/**
 * Bytes a view sends to the GPU per animation frame before the first draw
 * of a large level. Chromium copies a buffer to the GPU process within the
 * call that hands it over, at about 2–4 ms per megabyte with SwiftShader on
 * a loaded machine, and more when a frame's buffers pass its transfer
 * space: a 1 M-face level (30–45 MB) in one frame would hold the page for
 * 40–130 ms, and 8 MB frames of a 1.2 M-triangle file took 56–76 ms each
 * where 4 MB ones stay under 50.
 */
export const UPLOAD_BYTES_PER_FRAME = 4 * 1024 * 1024;

/** Milliseconds a view waits for the GPU to take a frame's uploads before it sends more or draws anyway. */
const FENCE_PATIENCE_MS = 5000;

/**
 * Whether WebGL draws on the CPU (SwiftShader, llvmpipe: a machine or VM
 * without a usable GPU), asked of a throwaway context. There, 4× MSAA
 * multiplies the raster work of every triangle: a 1 M-face level took 1.5–2.5 s
 * to appear with it and 1.2–1.3 s without, measured with `npm run bench`.
 */
function softwareRendered(): boolean {
  const gl =
    document.createElement('canvas').getContext('webgl2') ?? document.createElement('canvas').getContext('webgl');
  if (!gl) return false;
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  const renderer = String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
  gl.getExtension('WEBGL_lose_context')?.loseContext();
  return /swiftshader|llvmpipe|softpipe|software/i.test(renderer);
}

export class SharedRenderer {
  readonly renderer: WebGLRenderer;
  private width = 1;
  private height = 1;
  private readonly clearColor = new Color();
  private readonly views = new Set<() => void>();
  /** Attributes {@link upload} has sent to the GPU (or let the next draw send), until their geometry is disposed. */
  private onGpu = new WeakSet<Attribute>();
  /** The fence after the last frame's uploads, until the GPU has passed it. */
  private pendingFence: { sync: WebGLSync | null; since: number } | null = null;
  /** Parted attributes with a buffer, until their geometry is disposed. */
  private readonly parted = new Set<PartedAttribute>();
  /** Geometries whose disposal {@link upload} listens to. */
  private readonly watched = new WeakSet<BufferGeometry>();
  /** Draws nothing: its one object only makes three.js upload a buffer. */
  private readonly uploadScene = new Scene();
  private readonly uploadCamera = new OrthographicCamera();
  private readonly uploadMesh = new Mesh(undefined, new MeshBasicMaterial());

  constructor() {
    // Multisampled on a GPU, where it costs little; not on a software renderer.
    this.renderer = new WebGLRenderer({ antialias: !softwareRendered(), alpha: true });
    // three.js rebuilds its GPU state when a lost context comes back; the views then draw again.
    this.renderer.domElement.addEventListener('webglcontextrestored', () => {
      this.onGpu = new WeakSet();
      this.pendingFence = null;
      // Their buffers went with the context: made and filled again before the next draw.
      for (const attribute of this.parted) forgetBuffer(attribute);
      this.parted.clear();
      for (const redraw of this.views) redraw();
    });
    // No bounding sphere (a pass over every vertex): the mesh draws nothing anyway.
    this.uploadMesh.frustumCulled = false;
    this.uploadScene.add(this.uploadMesh);
    // Its shader, given to the GPU process now: linked long before a first use would wait for it.
    this.renderer.compile(this.uploadScene, this.uploadCamera);
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
    this.complete(scene);
    const r = this.renderer;
    r.setViewport(0, 0, width, height);
    r.setScissor(0, 0, width, height);
    r.setClearColor(this.clearColor.set(background ?? '#000000'), background ? 1 : 0);
    r.render(scene, camera);
    // WebGL's origin is the bottom-left corner; the canvas image's is the top-left.
    target.clearRect(0, 0, width, height);
    target.drawImage(r.domElement, 0, this.height - height, width, height, 0, 0, width, height);
  }

  /**
   * Spreads the upload of `geometries` (what a view is about to draw) over
   * animation frames: when what is not yet on the GPU exceeds
   * {@link UPLOAD_BYTES_PER_FRAME}, sends whole buffers and parts of
   * {@link PartedAttribute}s up to about that many bytes and returns true
   * (the view draws in a later frame); returns false when the draw may go
   * ahead, sending the rest itself.
   */
  upload(geometries: readonly BufferGeometry[]): boolean {
    this.freeDropped();
    const pending: { attribute: Attribute | PartedAttribute; index: boolean }[] = [];
    const hurried: PartedAttribute[] = [];
    let total = 0;
    for (const geometry of geometries) {
      const attributes = [...Object.values(geometry.attributes)].map((attribute) => ({ attribute, index: false }));
      if (geometry.index) attributes.push({ attribute: geometry.index, index: true });
      for (const entry of attributes) {
        const attribute = entry.attribute as Attribute | PartedAttribute;
        if (pending.some((p) => p.attribute === attribute) || hurried.includes(attribute as PartedAttribute)) continue;
        if (attribute instanceof PartedAttribute) {
          if (attribute.complete) continue;
          if (attribute.hurried) {
            hurried.push(attribute);
            continue;
          }
          total += attribute.array.byteLength - attribute.sent;
        } else {
          if (this.onGpu.has(attribute)) continue;
          total += bytesOf(attribute);
        }
        pending.push({ attribute, index: entry.index });
      }
      this.watch(geometry);
    }
    // A view with nothing to send draws, whatever another view's uploads left for the GPU.
    if (pending.length === 0 && hurried.length === 0) return false;
    if (this.gpuBusy()) return true;
    for (const attribute of hurried) this.fill(attribute, Number.POSITIVE_INFINITY);
    const budget = total <= UPLOAD_BYTES_PER_FRAME ? Number.POSITIVE_INFINITY : UPLOAD_BYTES_PER_FRAME;
    let left = budget;
    for (const { attribute, index } of pending) {
      if (left <= 0) break;
      if (attribute instanceof PartedAttribute) {
        left -= this.fill(attribute, left);
        continue;
      }
      // Within the budget, the draw sends it.
      if (budget === Number.POSITIVE_INFINITY) {
        this.onGpu.add(attribute);
        continue;
      }
      const bytes = bytesOf(attribute);
      if (left < budget && bytes > left) break;
      this.send(attribute, index);
      this.onGpu.add(attribute);
      left -= bytes;
    }
    if (budget === Number.POSITIVE_INFINITY) return false;
    this.fence();
    return true;
  }

  /**
   * Marks the end of a frame's uploads: the next frame sends nothing until
   * the GPU has taken them (WebGL 2's fence, asked without waiting). The
   * GPU process works through a frame's bytes at its own pace (a few
   * milliseconds a megabyte when idle, ten times that on a loaded machine,
   * and a new buffer of 200 MB is cleared first, 0.1–0.5 s); a call that
   * finds its transfer space still full holds the page until it is free.
   */
  private fence(): void {
    const gl = this.renderer.getContext();
    if (!(gl instanceof WebGL2RenderingContext)) return;
    this.pendingFence = { sync: gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0), since: performance.now() };
    // Sends the fence with the frame's commands (otherwise it waits for the next flush).
    gl.flush();
  }

  /** Whether the GPU has not yet taken the last frame's uploads (given up after {@link FENCE_PATIENCE_MS}). */
  private gpuBusy(): boolean {
    const fence = this.pendingFence;
    if (!fence) return false;
    const gl = this.renderer.getContext() as WebGL2RenderingContext;
    const signaled = fence.sync !== null && gl.getSyncParameter(fence.sync, gl.SYNC_STATUS) === gl.SIGNALED;
    // A lost context never signals: draw anyway after a while.
    if (!signaled && performance.now() - fence.since < FENCE_PATIENCE_MS) return true;
    gl.deleteSync(fence.sync);
    this.pendingFence = null;
    return false;
  }

  /**
   * Sends up to `bytes` more of `attribute` (all of it when infinite),
   * making its buffer at its full size first; returns the bytes sent.
   */
  private fill(attribute: PartedAttribute, bytes: number): number {
    const gl = this.renderer.getContext();
    const array = attribute.array;
    if (attribute.buffer === null) {
      attribute.buffer = gl.createBuffer();
      attribute.sent = 0;
      // Tells three the buffer changed (it keeps a GLBufferAttribute's buffer by version).
      attribute.version++;
      gl.bindBuffer(gl.ARRAY_BUFFER, attribute.buffer);
      gl.bufferData(gl.ARRAY_BUFFER, array.byteLength, gl.STATIC_DRAW);
      this.parted.add(attribute);
    } else gl.bindBuffer(gl.ARRAY_BUFFER, attribute.buffer);
    const start = attribute.sent;
    const end = Math.min(array.byteLength, start + Math.max(4, Math.floor(bytes / 4) * 4));
    gl.bufferSubData(gl.ARRAY_BUFFER, start, array.subarray(start / 4, end / 4));
    // Vertex array objects keep their own bindings: unbinding the array buffer changes no draw.
    gl.bindBuffer(gl.ARRAY_BUFFER, null);
    attribute.sent = end;
    if (end === array.byteLength) {
      attribute.hurried = false;
      attribute.completedAt = performance.now();
    }
    return end - start;
  }

  /** Frees the buffers of parted attributes taken off their geometries (PartedAttribute.drop). */
  private freeDropped(): void {
    for (const attribute of this.parted) {
      if (!attribute.dropped) continue;
      this.renderer.getContext().deleteBuffer(attribute.buffer);
      forgetBuffer(attribute);
      this.parted.delete(attribute);
    }
  }

  /** Sends what is missing of the parted attributes `scene` draws (a draw that no upload spread). */
  private complete(scene: Scene): void {
    this.freeDropped();
    scene.traverseVisible((object) => {
      const geometry = (object as Partial<Mesh>).geometry;
      if (!geometry) return;
      for (const attribute of Object.values(geometry.attributes) as unknown[]) {
        if (!(attribute instanceof PartedAttribute) || attribute.complete) continue;
        this.fill(attribute, Number.POSITIVE_INFINITY);
        this.watch(geometry);
      }
    });
  }

  /** Makes three.js upload one buffer: an object drawing nothing (draw range 0) whose geometry holds it. */
  private send(attribute: Attribute, index: boolean): void {
    const geometry = new BufferGeometry();
    if (index) geometry.setIndex(attribute as BufferAttribute);
    else geometry.setAttribute('position', attribute);
    geometry.setDrawRange(0, 0);
    // three sorts objects by their bounding sphere and would compute it from the buffer: a pass over
    // every vertex, and a NaN radius (a console error) for a fat line's interleaved ends.
    geometry.boundingSphere = new Sphere();
    this.uploadMesh.geometry = geometry;
    const r = this.renderer;
    r.setViewport(0, 0, 1, 1);
    r.setScissor(0, 0, 1, 1);
    r.render(this.uploadScene, this.uploadCamera);
    // Frees three's record of the helper geometry, not the buffer: it belongs to the level's geometry.
    geometry.setIndex(null);
    geometry.deleteAttribute('position');
    geometry.dispose();
    this.uploadMesh.geometry = new BufferGeometry();
  }

  /** Forgets a geometry's buffers when three frees them (its dispose). */
  private watch(geometry: BufferGeometry): void {
    if (this.watched.has(geometry)) return;
    this.watched.add(geometry);
    const forget = () => {
      if (geometry.index) this.onGpu.delete(geometry.index);
      for (const attribute of Object.values(geometry.attributes) as (Attribute | PartedAttribute)[]) {
        if (!(attribute instanceof PartedAttribute)) this.onGpu.delete(attribute);
        else if (this.parted.delete(attribute)) {
          // three frees the buffer of an attribute it has drawn, not of one only sent.
          this.renderer.getContext().deleteBuffer(attribute.buffer);
          forgetBuffer(attribute);
        }
      }
      this.watched.delete(geometry);
      geometry.removeEventListener('dispose', forget);
    };
    geometry.addEventListener('dispose', forget);
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

/** Leaves `attribute` without a buffer: the next upload or draw makes one and sends it all again. */
function forgetBuffer(attribute: PartedAttribute): void {
  attribute.buffer = null as unknown as WebGLBuffer;
  attribute.sent = 0;
  attribute.hurried = false;
}

function bytesOf(attribute: Attribute): number {
  return 'isInterleavedBufferAttribute' in attribute ? attribute.data.array.byteLength : attribute.array.byteLength;
}

let shared: SharedRenderer | null = null;

/** The page's renderer, made on first use. */
export function sharedRenderer(): SharedRenderer {
  shared ??= new SharedRenderer();
  return shared;
}
