/**
 * What the Export menu and Ctrl+C do: PNG (side by side, every pane), SVG,
 * PDF, EPS (the first pane's vector figure), OFF/OBJ/PLY/STL downloads named after model, scheme and level (and saying
 * so in a comment inside), and the view as a PNG on the clipboard. Failures
 * go to the shell's one error display.
 */
import type { MeshFormat } from '../core/mesh';
import type { FigureFormat } from '../render/figure';
import { pictureGrid } from '../render/picture-grid';
import { saveBlob } from '../ui/save-blob';
import { exportComment, exportFileName } from '../viewer/file-names';
import { schemeInfo } from '../viewer/scheme-info';
import type { SubdivViewer } from '../viewer/subdiv-viewer';

const COPY_UNSUPPORTED =
  'This browser cannot put images on the clipboard; use Export → PNG to save the picture instead.';

/** Width and height from a PNG's header (its IHDR chunk, bytes 16–23). */
export async function pngSize(png: Blob): Promise<{ width: number; height: number }> {
  const header = new DataView(await png.slice(0, 24).arrayBuffer());
  return { width: header.getUint32(16), height: header.getUint32(20) };
}

/** Why a copy failed, as the user can act on it. */
function copyError(error: unknown): Error {
  const name = error instanceof DOMException ? error.name : '';
  if (name === 'NotAllowedError' || name === 'SecurityError') {
    return new Error(
      'The image was not copied: the browser did not allow this page to write to the clipboard (permission denied, or the page was not focused).',
    );
  }
  if (name === 'NotSupportedError' || error instanceof ReferenceError) return new Error(COPY_UNSUPPORTED);
  return error instanceof Error ? error : new Error(String(error));
}

export class ExportActions {
  /** `panes`: the viewers side by side (the first is `viewer`); one viewer when side by side is off. */
  constructor(
    private readonly viewer: SubdivViewer,
    private readonly showError: (source: string, error: unknown) => void,
    private readonly panes: () => SubdivViewer[] = () => [viewer],
    private readonly notify: (text: string) => void = () => {},
  ) {}

  async png(scale: number, transparent: boolean): Promise<void> {
    try {
      saveBlob(await this.picture(scale, transparent), this.fileName('png'));
    } catch (error) {
      this.showError(this.fileName('png'), error);
    }
  }

  /** The view as a PNG; side by side, every pane in its place, labelled with its scheme and level. */
  private async picture(scale: number, transparent: boolean): Promise<Blob> {
    const panes = this.panes();
    if (panes.length < 2) return this.viewer.exportPng(scale, transparent);
    const pictures = await Promise.all(
      panes.map(async (pane) => ({
        png: await pane.exportPng(scale, transparent),
        label: `${schemeInfo(pane.state.scheme).label} · level ${pane.state.level}`,
      })),
    );
    return pictureGrid(pictures, scale, transparent);
  }

  /** Copies the view as a PNG and says so ("Copied a 1280×800 PNG to the clipboard"), or says why it could not. */
  async copyImage(transparent: boolean): Promise<void> {
    if (this.viewer.state.levelCount === 0) return;
    if (typeof ClipboardItem === 'undefined' || !navigator.clipboard?.write) {
      this.showError('Clipboard', new Error(COPY_UNSUPPORTED));
      return;
    }
    try {
      // Hand the promise to ClipboardItem at once: Safari needs the user gesture to be current.
      const png = this.picture(1, transparent);
      await navigator.clipboard.write([new ClipboardItem({ 'image/png': png })]);
      const { width, height } = await pngSize(await png);
      this.notify(`Copied a ${width}×${height} PNG to the clipboard.`);
    } catch (error) {
      this.showError('Clipboard', copyError(error));
    }
  }

  /** The view as a vector figure: SVG, PDF or EPS (render/figure.ts), titled like the file. */
  figure(format: FigureFormat, transparent: boolean): void {
    const name = this.fileName(format);
    try {
      const title = name.replace(/\.[a-z]+$/, '');
      const blob =
        format === 'svg'
          ? new Blob([this.viewer.exportSvg(transparent)], { type: 'image/svg+xml' })
          : format === 'pdf'
            ? new Blob([this.viewer.exportPdf(transparent, title) as BlobPart], { type: 'application/pdf' })
            : new Blob([this.viewer.exportEps(transparent, title)], { type: 'application/postscript' });
      saveBlob(blob, name);
    } catch (error) {
      this.showError(name, error);
    }
  }

  async mesh(format: MeshFormat): Promise<void> {
    try {
      const s = this.viewer.state;
      const comment = exportComment(s.modelName, schemeInfo(s.scheme).label, s.level);
      saveBlob(await this.viewer.exportMesh(format, comment), this.fileName(format));
    } catch (error) {
      this.showError(this.fileName(format), error);
    }
  }

  private fileName(extension: string): string {
    const s = this.viewer.state;
    // Side by side (the PNG): the schemes joined, cube-catmull-clark-loop-L2.png.
    const schemes = extension === 'png' ? this.panes().map((p) => p.state.scheme) : [s.scheme];
    return exportFileName(s.modelName, schemes.join('-'), s.level, extension);
  }
}
