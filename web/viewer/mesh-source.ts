/**
 * Where a mesh file comes from: a dropped or picked File, a gallery sample,
 * or `?src=URL`. Each returns the file's bytes (binary PLY and STL are not
 * text) and the name shown to the user; each refuses what it should not
 * read (wrong scheme, too large) with an Error whose message says why. What
 * the bytes are (a mesh format, or a PNG dropped by mistake) the core says:
 * it reads them anyway, and the CLI gets the same words.
 */
import type { ReadFormat } from '../core/mesh';
import { CancelledError } from '../core/worker-client';

/** Largest file the app reads: the core's heap ends at 4 GB and text is about 3× the mesh. */
export const MAX_FILE_BYTES = 256 * 1024 * 1024;
/** Largest download through `?src=`. */
export const MAX_URL_BYTES = 64 * 1024 * 1024;

export interface MeshText {
  /** File name shown to the user and used in export names. */
  name: string;
  /** The file: bytes as read, or a string (a caller's OFF/OBJ text). */
  text: string | Uint8Array;
  format: ReadFormat;
}

/** A load failure that names its source (file name or URL). */
export class LoadError extends Error {
  constructor(
    readonly source: string,
    message: string,
  ) {
    super(message);
    this.name = 'LoadError';
  }
}

/**
 * OFF, OBJ, PLY or STL from the extension; otherwise `'auto'`: the core
 * tells the format from the first bytes, or says what else the file is.
 */
export function detectFormat(name: string): ReadFormat {
  const ext = /\.(off|obj|ply|stl)$/i.exec(name.trim());
  return ext ? (ext[1].toLowerCase() as ReadFormat) : 'auto';
}

/** A mesh file named `name`, with its format (see {@link detectFormat}). */
export function meshText(name: string, text: string | Uint8Array): MeshText {
  return { name, text, format: detectFormat(name) };
}

/** Reads a dropped or picked file. */
export async function readFile(file: File): Promise<MeshText> {
  if (file.size > MAX_FILE_BYTES) {
    throw new LoadError(file.name, `The file is ${formatMB(file.size)}; the limit is ${formatMB(MAX_FILE_BYTES)}.`);
  }
  if (file.size === 0) throw new LoadError(file.name, 'The file is empty.');
  return meshText(file.name, new Uint8Array(await file.arrayBuffer()));
}

function formatMB(bytes: number): string {
  return `${(bytes / (1024 * 1024)).toFixed(bytes < 1024 * 1024 ? 2 : 0)} MB`;
}

/** The last path segment of a URL, decoded, as a display name. */
export function nameFromUrl(url: URL): string {
  const segment = url.pathname.split('/').filter(Boolean).pop() ?? url.hostname;
  try {
    return decodeURIComponent(segment);
  } catch {
    return segment;
  }
}

/**
 * Fetches a mesh from `src` (absolute, or relative to `base`). Only http and
 * https; reading stops as soon as more than `maxBytes` arrived, whatever the
 * Content-Length said. Aborting `signal` rejects with CancelledError.
 */
export async function fetchMesh(
  src: string,
  base: string,
  maxBytes = MAX_URL_BYTES,
  signal?: AbortSignal,
): Promise<MeshText> {
  try {
    return await download(src, base, maxBytes, signal);
  } catch (error) {
    if (signal?.aborted) throw new CancelledError();
    throw error;
  }
}

/** `src` resolved against `base`; refuses (LoadError) what is not a valid http or https URL. */
export function httpUrl(src: string, base: string): URL {
  let url: URL;
  try {
    url = new URL(src, base);
  } catch {
    throw new LoadError(src, 'This is not a valid URL.');
  }
  if (url.protocol !== 'http:' && url.protocol !== 'https:') {
    throw new LoadError(src, `Only http and https URLs can be loaded, not ${url.protocol}`);
  }
  return url;
}

async function download(src: string, base: string, maxBytes: number, signal?: AbortSignal): Promise<MeshText> {
  const url = httpUrl(src, base);
  const name = nameFromUrl(url);
  let response: Response;
  try {
    response = await fetch(url, { credentials: 'omit', signal });
  } catch {
    throw new LoadError(
      src,
      'The download failed (network error, or the server does not allow cross-origin requests).',
    );
  }
  if (!response.ok) throw new LoadError(src, `The server answered ${response.status} ${response.statusText}`.trim());
  if (response.headers.get('content-type')?.startsWith('text/html')) {
    throw new LoadError(src, 'The server sent a web page, not a mesh: is the URL right?');
  }
  const declared = Number(response.headers.get('content-length') ?? 'NaN');
  if (declared > maxBytes) {
    throw new LoadError(src, `The file is ${formatMB(declared)}; the limit for URLs is ${formatMB(maxBytes)}.`);
  }
  const bytes = await readLimited(response, maxBytes, src);
  return meshText(name, bytes);
}

/** The body of `response` as bytes, refused (LoadError about `src`) as soon as more than `maxBytes` arrived. */
export async function readLimited(response: Response, maxBytes: number, src: string): Promise<Uint8Array> {
  if (!response.body) return new Uint8Array(await response.arrayBuffer());
  const reader = response.body.getReader();
  const chunks: Uint8Array[] = [];
  let total = 0;
  for (;;) {
    const { done, value } = await reader.read();
    if (done) break;
    total += value.byteLength;
    if (total > maxBytes) {
      await reader.cancel();
      throw new LoadError(src, `The file is larger than the limit for URLs (${formatMB(maxBytes)}).`);
    }
    chunks.push(value);
  }
  const bytes = new Uint8Array(total);
  let offset = 0;
  for (const chunk of chunks) {
    bytes.set(chunk, offset);
    offset += chunk.byteLength;
  }
  return bytes;
}
