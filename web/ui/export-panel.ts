/** Export: PNG (×1/×2/×4, optional transparent background), copy image, SVG, PDF, EPS, OFF, OBJ, PLY, STL. */
import type { MeshFormat } from '../core/mesh';
import type { FigureFormat } from '../render/figure';
import type { ViewerState } from '../viewer/subdiv-viewer';
import { button, dropdown, el, uniqueId } from './dom';

export interface ExportPanelHandlers {
  onPng: (scale: number, transparent: boolean) => void;
  onCopy: (transparent: boolean) => void;
  /** A vector figure of the view (SVG, PDF for pdfLaTeX, EPS for latex + dvips). */
  onFigure: (format: FigureFormat, transparent: boolean) => void;
  onMesh: (format: MeshFormat) => void;
}

export class ExportPanel {
  readonly element: HTMLElement;
  private readonly scale: HTMLSelectElement;
  private readonly transparent: HTMLInputElement;
  private readonly buttons: HTMLButtonElement[];

  constructor(handlers: ExportPanelHandlers) {
    const scaleId = uniqueId('png-scale');
    this.scale = el('select', { testId: 'export.scale', attrs: { id: scaleId } });
    for (const s of [1, 2, 4]) this.scale.append(el('option', { text: `×${s}`, attrs: { value: String(s) } }));
    const transparentId = uniqueId('transparent');
    this.transparent = el('input', { testId: 'export.transparent', attrs: { type: 'checkbox', id: transparentId } });
    const transparent = () => this.transparent.checked;
    this.buttons = [
      button(
        'PNG',
        'export.png',
        () => handlers.onPng(Number(this.scale.value), transparent()),
        'Save the view as PNG',
      ),
      button('Copy image', 'export.copy', () => handlers.onCopy(transparent()), 'Copy the view as PNG (Ctrl+C)'),
      button('SVG', 'export.svg', () => handlers.onFigure('svg', transparent()), 'Save the view as SVG (polygons)'),
      button(
        'PDF',
        'export.pdf',
        () => handlers.onFigure('pdf', transparent()),
        'Save the view as PDF (vector, for LaTeX)',
      ),
      button(
        'EPS',
        'export.eps',
        () => handlers.onFigure('eps', transparent()),
        'Save the view as EPS (vector, for latex + dvips; opaque)',
      ),
      button('OFF', 'export.off', () => handlers.onMesh('off'), 'Save the shown level as OFF'),
      button('OBJ', 'export.obj', () => handlers.onMesh('obj'), 'Save the shown level as OBJ'),
      button('PLY', 'export.ply', () => handlers.onMesh('ply'), 'Save the shown level as PLY (ASCII)'),
      button('STL', 'export.stl', () => handlers.onMesh('stl'), 'Save the shown level as STL (binary, triangles)'),
    ];
    this.buttons[1].setAttribute('aria-keyshortcuts', 'Control+C');
    this.element = dropdown(
      'Export',
      'export-panel',
      el(
        'div',
        { className: 'row' },
        el('label', { attrs: { for: scaleId }, text: 'PNG size' }),
        this.scale,
        el('label', { className: 'check', attrs: { for: transparentId } }, this.transparent, ' Transparent'),
      ),
      // A row a kind: pictures, vector figures, mesh files.
      el('div', { className: 'row wrap' }, ...this.buttons.slice(0, 2)),
      el(
        'div',
        { className: 'row wrap' },
        el('span', { className: 'row-label', text: 'Figure' }),
        ...this.buttons.slice(2, 5),
      ),
      el(
        'div',
        { className: 'row wrap' },
        el('span', { className: 'row-label', text: 'Mesh' }),
        ...this.buttons.slice(5),
      ),
    );
  }

  update(state: ViewerState): void {
    for (const b of this.buttons) b.disabled = state.levelCount === 0;
  }
}
