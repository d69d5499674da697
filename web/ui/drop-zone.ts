/**
 * Drag-and-drop anywhere on the page: a full-page target appears while a
 * file is dragged over the window and the first dropped file is handed on.
 */
import { el } from './dom';

export class DropZone {
  readonly element: HTMLElement;
  private depth = 0;

  constructor(
    private readonly target: HTMLElement | Document,
    private readonly onFile: (file: File) => void,
  ) {
    this.element = el(
      'div',
      { testId: 'dropzone', className: 'drop-zone', attrs: { 'aria-hidden': 'true' } },
      el('div', { className: 'drop-zone-label', text: 'Drop an OFF, OBJ, PLY or STL file to open it' }),
    );
    this.element.hidden = true;
    target.addEventListener('dragenter', this.onDragEnter as EventListener);
    target.addEventListener('dragover', this.onDragOver as EventListener);
    target.addEventListener('dragleave', this.onDragLeave as EventListener);
    target.addEventListener('drop', this.onDrop as EventListener);
  }

  dispose(): void {
    this.target.removeEventListener('dragenter', this.onDragEnter as EventListener);
    this.target.removeEventListener('dragover', this.onDragOver as EventListener);
    this.target.removeEventListener('dragleave', this.onDragLeave as EventListener);
    this.target.removeEventListener('drop', this.onDrop as EventListener);
  }

  private static carriesFiles(event: DragEvent): boolean {
    return event.dataTransfer?.types.includes('Files') ?? false;
  }

  private readonly onDragEnter = (event: DragEvent) => {
    if (!DropZone.carriesFiles(event)) return;
    event.preventDefault();
    this.depth++;
    this.element.hidden = false;
  };

  private readonly onDragOver = (event: DragEvent) => {
    if (!DropZone.carriesFiles(event)) return;
    // Without preventDefault the browser would open the file itself.
    event.preventDefault();
    if (event.dataTransfer) event.dataTransfer.dropEffect = 'copy';
    this.element.hidden = false;
  };

  private readonly onDragLeave = (event: DragEvent) => {
    if (!DropZone.carriesFiles(event)) return;
    this.depth = Math.max(0, this.depth - 1);
    if (this.depth === 0) this.element.hidden = true;
  };

  private readonly onDrop = (event: DragEvent) => {
    if (!DropZone.carriesFiles(event)) return;
    event.preventDefault();
    this.depth = 0;
    this.element.hidden = true;
    const file = event.dataTransfer?.files[0];
    if (file) this.onFile(file);
  };
}
