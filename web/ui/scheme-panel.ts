/**
 * Scheme picker: every scheme the core offers, a one-line description, for
 * schemes that need triangles a note and a "Triangulate first" option when
 * the loaded mesh has other faces, and quad-triangle's "Fixed boundary".
 */

import type { SchemeName } from '../core/mesh';
import { schemeInfo } from '../viewer/scheme-info';
import type { ViewerState } from '../viewer/subdiv-viewer';
import { el, section, uniqueId } from './dom';

export interface SchemePanelHandlers {
  onScheme: (scheme: SchemeName) => void;
  onTriangulate: (triangulate: boolean) => void;
  /** quad-triangle: keep border vertices on the control border (smoothBoundary = false). */
  onFixedBoundary: (fixed: boolean) => void;
}

/** What the panel shows besides the viewer's state. */
export interface SchemeExtras {
  /** The scheme needs triangles (default: scheme-info's; custom rules depend on their host). */
  needsTriangles?: boolean;
  /** Who needs them, for the note (default: the scheme's label), e.g. "The PTQ host". */
  needsTrianglesWho?: string;
  /** quad-triangle's border option. */
  fixedBoundary: boolean;
  /** A scheme being switched to: the menu shows it while its levels are computed. */
  pending?: SchemeName;
}

export class SchemePanel {
  readonly element: HTMLElement;
  private readonly select: HTMLSelectElement;
  private readonly description: HTMLElement;
  private readonly triangles: HTMLElement;
  private readonly triangleNote: HTMLElement;
  private readonly triangulate: HTMLInputElement;
  private readonly fixedBoundary: HTMLInputElement;
  private readonly fixedBoundaryRow: HTMLElement;

  constructor(handlers: SchemePanelHandlers) {
    const selectId = uniqueId('scheme');
    const descriptionId = uniqueId('scheme-description');
    this.select = el('select', {
      testId: 'controls.scheme',
      attrs: { id: selectId, 'aria-describedby': descriptionId },
    });
    this.select.disabled = true;
    this.select.append(el('option', { text: 'Loading the core…' }));
    this.select.addEventListener('change', () => handlers.onScheme(this.select.value as SchemeName));
    this.description = el('p', {
      testId: 'controls.scheme-description',
      className: 'hint',
      attrs: { id: descriptionId },
    });
    const checkboxId = uniqueId('triangulate');
    this.triangulate = el('input', { testId: 'controls.triangulate', attrs: { type: 'checkbox', id: checkboxId } });
    this.triangulate.addEventListener('change', () => handlers.onTriangulate(this.triangulate.checked));
    this.triangleNote = el('p', { testId: 'controls.triangle-note', className: 'note' });
    this.triangles = el(
      'div',
      { className: 'triangulate' },
      this.triangleNote,
      el('label', { attrs: { for: checkboxId } }, this.triangulate, ' Triangulate first (CGAL triangulate_faces)'),
    );
    const fixedId = uniqueId('fixed-boundary');
    this.fixedBoundary = el('input', { testId: 'controls.fixed-boundary', attrs: { type: 'checkbox', id: fixedId } });
    this.fixedBoundary.addEventListener('change', () => handlers.onFixedBoundary(this.fixedBoundary.checked));
    this.fixedBoundaryRow = el(
      'label',
      { className: 'check', attrs: { for: fixedId } },
      this.fixedBoundary,
      ' Fixed boundary (border vertices stay on the control border)',
    );
    this.element = section(
      'Scheme',
      'scheme-panel',
      el('label', { attrs: { for: selectId }, text: 'Subdivision scheme' }),
      this.select,
      this.description,
      this.triangles,
      this.fixedBoundaryRow,
    );
  }

  /** Fills the picker with the core's schemes. */
  setSchemes(names: readonly string[], current: SchemeName): void {
    this.select.replaceChildren(
      ...names.map((name) => el('option', { text: schemeInfo(name).label, attrs: { value: name } })),
    );
    this.select.value = current;
    this.select.disabled = false;
  }

  update(state: ViewerState, extras: SchemeExtras): void {
    const scheme = extras.pending ?? state.scheme;
    if (!this.select.disabled && this.select.value !== scheme) this.select.value = scheme;
    const info = schemeInfo(scheme);
    this.description.textContent = info.description;
    this.triangulate.checked = state.triangulate;
    const facts = state.facts;
    const others = facts ? facts.quads + facts.otherFaces : 0;
    const show = (extras.needsTriangles ?? info.needsTriangles) && others > 0;
    this.triangles.hidden = !show;
    this.triangleNote.textContent = show
      ? `${extras.needsTrianglesWho ?? info.label} needs triangles; this mesh has ${others} other face${others === 1 ? '' : 's'}.`
      : '';
    this.fixedBoundaryRow.hidden = scheme !== 'quad-triangle';
    this.fixedBoundary.checked = extras.fixedBoundary;
  }
}
