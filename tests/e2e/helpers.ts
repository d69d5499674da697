/**
 * Independent arithmetic for the end-to-end tests: expected counts from the
 * schemes' published refinement rules, a small OFF reader, camera-facing
 * face counts, and a PNG header/pixel reader. None of it uses the app's code.
 */
import { inflateSync } from 'node:zlib';

export interface Counts {
  vertices: number;
  edges: number;
  faces: number;
}

/** A closed mesh's counts plus the sum of its face degrees (= 2E). */
interface ClosedCounts extends Counts {
  corners: number;
}

/**
 * Counts after `levels` steps on a *closed* mesh, from each scheme's rules:
 * Catmull-Clark adds a vertex per edge and face, a quad per corner;
 * Loop a vertex per edge, 4 triangles per triangle; √3 a vertex per face,
 * 3 triangles per triangle; Doo-Sabin a vertex per corner and a face per
 * vertex, edge and face.
 */
export function expectedClosedCounts(scheme: string, start: Counts, levels: number): Counts {
  let c: ClosedCounts = { ...start, corners: 2 * start.edges };
  for (let i = 0; i < levels; i++) {
    const { vertices: v, edges: e, faces: f, corners } = c;
    switch (scheme) {
      case 'catmull-clark':
        c = { vertices: v + e + f, edges: 2 * e + corners, faces: corners, corners: 4 * corners };
        break;
      case 'loop':
        c = { vertices: v + e, edges: 2 * e + 3 * f, faces: 4 * f, corners: 12 * f };
        break;
      case 'sqrt3':
        c = { vertices: v + f, edges: e + 3 * f, faces: 3 * f, corners: 9 * f };
        break;
      case 'doo-sabin':
        c = { vertices: corners, edges: 4 * e, faces: v + e + f, corners: 8 * e };
        break;
      default:
        throw new Error(`no rule for ${scheme}`);
    }
  }
  return { vertices: c.vertices, edges: c.edges, faces: c.faces };
}

/** Counts after splitting every quad of a closed quad mesh along one diagonal. */
export function triangulatedQuads(c: Counts): Counts {
  return { vertices: c.vertices, edges: c.edges + c.faces, faces: 2 * c.faces };
}

export interface OffMesh {
  positions: number[][];
  faces: number[][];
}

/** Reads plain OFF (header, counts, vertices, faces; `#` comments). */
export function readOff(text: string): OffMesh {
  const tokens = text
    .split('\n')
    .map((line) => line.replace(/#.*/, '').trim())
    .filter((line) => line !== '')
    .join(' ')
    .split(/\s+/);
  if (!/OFF$/.test(tokens[0])) throw new Error(`not OFF: ${tokens[0]}`);
  const [nv, nf] = [Number(tokens[1]), Number(tokens[2])];
  let i = 4;
  const positions: number[][] = [];
  for (let k = 0; k < nv; k++) positions.push([Number(tokens[i++]), Number(tokens[i++]), Number(tokens[i++])]);
  const faces: number[][] = [];
  for (let k = 0; k < nf; k++) {
    const n = Number(tokens[i++]);
    faces.push(tokens.slice(i, i + n).map(Number));
    i += n;
  }
  return { positions, faces };
}

/** Distinct undirected edges of a polygon mesh. */
export function edgeCount(mesh: OffMesh): number {
  const keys = new Set<string>();
  for (const f of mesh.faces) {
    for (let k = 0; k < f.length; k++) {
      const a = f[k];
      const b = f[(k + 1) % f.length];
      keys.add(a < b ? `${a},${b}` : `${b},${a}`);
    }
  }
  return keys.size;
}

/**
 * Faces whose front side the camera at `eye` sees: (eye − centroid) · n > 0
 * with n the polygon's Newell normal (the usual back-face test for a
 * perspective camera).
 */
export function cameraFacingFaces(mesh: OffMesh, eye: readonly number[]): number {
  let count = 0;
  for (const f of mesh.faces) {
    const n = [0, 0, 0];
    const c = [0, 0, 0];
    for (let k = 0; k < f.length; k++) {
      const p = mesh.positions[f[k]];
      const q = mesh.positions[f[(k + 1) % f.length]];
      n[0] += (p[1] - q[1]) * (p[2] + q[2]);
      n[1] += (p[2] - q[2]) * (p[0] + q[0]);
      n[2] += (p[0] - q[0]) * (p[1] + q[1]);
      for (let d = 0; d < 3; d++) c[d] += p[d] / f.length;
    }
    const dot = (eye[0] - c[0]) * n[0] + (eye[1] - c[1]) * n[1] + (eye[2] - c[2]) * n[2];
    if (dot > 0) count++;
  }
  return count;
}

export const PNG_SIGNATURE = Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]);

export interface PngInfo {
  width: number;
  height: number;
  colorType: number;
  /** RGBA of pixel (x, y) (alpha 255 in an RGB image); only for 8-bit RGB and RGBA images. */
  pixel(x: number, y: number): [number, number, number, number];
}

/** Reads a PNG's header and, for 8-bit RGB and RGBA, its pixels (inflate + unfilter, per the PNG spec). */
export function readPng(bytes: Buffer): PngInfo {
  if (!bytes.subarray(0, 8).equals(PNG_SIGNATURE)) throw new Error('not a PNG (bad signature)');
  const width = bytes.readUInt32BE(16);
  const height = bytes.readUInt32BE(20);
  const bitDepth = bytes[24];
  const colorType = bytes[25];
  const idat: Buffer[] = [];
  for (let offset = 8; offset < bytes.length; ) {
    const length = bytes.readUInt32BE(offset);
    const type = bytes.toString('latin1', offset + 4, offset + 8);
    if (type === 'IDAT') idat.push(bytes.subarray(offset + 8, offset + 8 + length));
    offset += 12 + length;
  }
  let pixels: Uint8Array | null = null;
  const bpp = colorType === 2 ? 3 : 4;
  const stride = width * bpp;
  const decode = () => {
    const raw = inflateSync(Buffer.concat(idat));
    const out = new Uint8Array(height * stride);
    for (let y = 0; y < height; y++) {
      const filter = raw[y * (stride + 1)];
      for (let x = 0; x < stride; x++) {
        const value = raw[y * (stride + 1) + 1 + x];
        const a = x >= bpp ? out[y * stride + x - bpp] : 0;
        const b = y > 0 ? out[(y - 1) * stride + x] : 0;
        const c = x >= bpp && y > 0 ? out[(y - 1) * stride + x - bpp] : 0;
        let predicted = 0;
        if (filter === 1) predicted = a;
        else if (filter === 2) predicted = b;
        else if (filter === 3) predicted = Math.floor((a + b) / 2);
        else if (filter === 4) {
          const p = a + b - c;
          const [pa, pb, pc] = [Math.abs(p - a), Math.abs(p - b), Math.abs(p - c)];
          predicted = pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
        }
        out[y * stride + x] = (value + predicted) & 0xff;
      }
    }
    return out;
  };
  return {
    width,
    height,
    colorType,
    pixel(x, y) {
      if (bitDepth !== 8 || (colorType !== 6 && colorType !== 2))
        throw new Error(`pixel(): only 8-bit RGB or RGBA (got ${bitDepth}/${colorType})`);
      pixels ??= decode();
      const i = y * stride + x * bpp;
      return [pixels[i], pixels[i + 1], pixels[i + 2], bpp === 4 ? pixels[i + 3] : 255];
    },
  };
}

/** A regular n×n quad grid in z = 0 as OFF text (open, one boundary loop), slightly waved. */
export function quadGridOff(n: number): string {
  const v: string[] = [];
  const f: string[] = [];
  for (let j = 0; j <= n; j++) {
    for (let i = 0; i <= n; i++)
      v.push(`${i / n} ${j / n} ${(0.05 * Math.sin(i * 0.3) * Math.cos(j * 0.2)).toFixed(6)}`);
  }
  for (let j = 0; j < n; j++) {
    for (let i = 0; i < n; i++) {
      const a = j * (n + 1) + i;
      f.push(`4 ${a} ${a + 1} ${a + n + 2} ${a + n + 1}`);
    }
  }
  return `OFF\n${v.length} ${f.length} 0\n${v.join('\n')}\n${f.join('\n')}\n`;
}

export interface Camera {
  position: readonly number[];
  target: readonly number[];
  up: readonly number[];
  /** Vertical field of view, degrees. */
  fov: number;
  width: number;
  height: number;
  /** Where the target is drawn, in NDC (the view's shift that keeps the model clear of its panels); default 0 0. */
  offset?: readonly [number, number];
}

const sub3 = (a: readonly number[], b: readonly number[]) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const dot3 = (a: readonly number[], b: readonly number[]) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross3 = (a: readonly number[], b: readonly number[]) => [
  a[1] * b[2] - a[2] * b[1],
  a[2] * b[0] - a[0] * b[2],
  a[0] * b[1] - a[1] * b[0],
];
const unit3 = (a: readonly number[]) => {
  const l = Math.hypot(a[0], a[1], a[2]);
  return [a[0] / l, a[1] / l, a[2] / l];
};

/**
 * For each camera-facing face: its centroid projected to screen pixels (a
 * pinhole camera looking from `position` at `target`) and its depth along the
 * viewing direction.
 */
export function projectedFacingFaces(mesh: OffMesh, camera: Camera): { x: number; y: number; depth: number }[] {
  const forward = unit3(sub3(camera.target, camera.position));
  const right = unit3(cross3(forward, camera.up));
  const up = cross3(right, forward);
  const t = Math.tan((camera.fov * Math.PI) / 360);
  const aspect = camera.width / camera.height;
  const [ox, oy] = camera.offset ?? [0, 0];
  const out: { x: number; y: number; depth: number }[] = [];
  for (const f of mesh.faces) {
    const single: OffMesh = { positions: mesh.positions, faces: [f] };
    if (cameraFacingFaces(single, camera.position) !== 1) continue;
    const c = [0, 1, 2].map((d) => f.reduce((s, i) => s + mesh.positions[i][d], 0) / f.length);
    // The screen centroid is the mean of the projected corners (as the SVG polygon's points).
    let x = 0;
    let y = 0;
    for (const i of f) {
      const v = sub3(mesh.positions[i], camera.position);
      const z = dot3(v, forward);
      x += ((dot3(v, right) / (z * t * aspect) + ox + 1) / 2) * camera.width;
      y += ((1 - dot3(v, up) / (z * t) - oy) / 2) * camera.height;
    }
    out.push({ x: x / f.length, y: y / f.length, depth: dot3(sub3(c, camera.position), forward) });
  }
  return out;
}
