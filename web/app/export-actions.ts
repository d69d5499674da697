/**
 * What the Export menu and Ctrl+C do: PNG, SVG, OFF/OBJ downloads named after
 * model, scheme and level, and the view as a PNG on the clipboard. Failures
 * go to the shell's one error display.
 */
import { saveBlob } from '../ui/save-blob';
import { exportFileName } from '../viewer/file-names';
import type { SubdivViewer } from '../viewer/subdiv-viewer';

export class ExportActions {
  constructor(
    private readonly viewer: SubdivViewer,
    private readonly showError: (source: string, error: unknown) => void,
  ) {}

  async png(scale: number, transparent: boolean): Promise<void> {
    try {
      saveBlob(await this.viewer.exportPng(scale, transparent), this.fileName('png'));
    } catch (error) {
      this.showError(this.fileName('png'), error);
    }
  }

  async copyImage(transparent: boolean): Promise<void> {
    if (this.viewer.state.levelCount === 0) return;
    try {
      // Hand the promise to ClipboardItem at once: Safari needs the user gesture to be current.
      const png = this.viewer.exportPng(1, transparent);
      await navigator.clipboard.write([new ClipboardItem({ 'image/png': png })]);
    } catch (error) {
      this.showError('Clipboard', error);
    }
  }

  svg(transparent: boolean): void {
    try {
      const svg = this.viewer.exportSvg(transparent);
      saveBlob(new Blob([svg], { type: 'image/svg+xml' }), this.fileName('svg'));
    } catch (error) {
      this.showError(this.fileName('svg'), error);
    }
  }

  async mesh(format: 'off' | 'obj'): Promise<void> {
    try {
      saveBlob(await this.viewer.exportMesh(format), this.fileName(format));
    } catch (error) {
      this.showError(this.fileName(format), error);
    }
  }

  private fileName(extension: string): string {
    const s = this.viewer.state;
    return exportFileName(s.modelName, s.scheme, s.level, extension);
  }
}
