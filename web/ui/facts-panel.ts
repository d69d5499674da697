/** Facts of the shown level, as the core computed them. */

import type { MeshFacts } from '../core/mesh';
import type { TagSummary, ViewerState } from '../viewer/subdiv-viewer';
import { el } from './dom';

const ROWS: readonly { key: string; label: string; value: (f: MeshFacts) => string }[] = [
  { key: 'vertices', label: 'Vertices', value: (f) => f.vertices.toLocaleString('en') },
  { key: 'edges', label: 'Edges', value: (f) => f.edges.toLocaleString('en') },
  { key: 'faces', label: 'Faces', value: (f) => f.faces.toLocaleString('en') },
  { key: 'components', label: 'Components', value: (f) => f.components.toLocaleString('en') },
  { key: 'boundaries', label: 'Boundaries', value: (f) => f.boundaries.toLocaleString('en') },
  { key: 'euler', label: 'Euler characteristic', value: (f) => String(f.eulerCharacteristic) },
  { key: 'genus', label: 'Genus', value: (f) => String(f.genus) },
  { key: 'face-types', label: 'Face types', value: faceTypes },
];

/** "8 triangles, 18 quads", "6 quads", "1,536 quads", "1 other polygon". */
export function faceTypes(f: MeshFacts): string {
  const parts: string[] = [];
  const add = (count: number, one: string, many: string) => {
    if (count > 0) parts.push(`${count.toLocaleString('en')} ${count === 1 ? one : many}`);
  };
  add(f.triangles, 'triangle', 'triangles');
  add(f.quads, 'quad', 'quads');
  add(f.otherFaces, 'other polygon', 'other polygons');
  return parts.join(', ') || 'none';
}

/**
 * Every edge of level 0 is a control edge; later levels carry the marks the
 * core kept (primal schemes only: dual schemes and √3 keep none, shown as –).
 */
function controlEdges(f: MeshFacts, level: number): string {
  if (level === 0) return f.edges.toLocaleString('en');
  return f.controlEdges > 0 ? f.controlEdges.toLocaleString('en') : '–';
}

const BOUNDARY_NAMES: Record<TagSummary['boundary'], string> = {
  edge: 'edges sharp',
  'edge-and-corner': 'edges and corners sharp',
  none: 'border faces holes',
};

/** "4 creases, 1 corner, 2 holes" (and the border mode and crease method when not the defaults), or "–". */
export function tagText(tags: TagSummary | null): string {
  if (!tags) return '–';
  const count = (n: number, one: string) => `${n} ${one}${n === 1 ? '' : 's'}`;
  const parts: string[] = [];
  if (tags.creases > 0) parts.push(count(tags.creases, 'crease'));
  if (tags.corners > 0) parts.push(count(tags.corners, 'corner'));
  if (tags.holes > 0) parts.push(count(tags.holes, 'hole'));
  if (tags.boundary !== 'edge') parts.push(`border: ${BOUNDARY_NAMES[tags.boundary]}`);
  if (tags.creaseMethod !== 'uniform') parts.push('Chaikin creasing');
  return parts.length > 0 ? parts.join(', ') : 'none';
}

export class FactsPanel {
  readonly element: HTMLElement;
  private readonly cells = new Map<string, HTMLElement>();
  private readonly model: HTMLElement;
  private readonly level: HTMLElement;
  private readonly controlEdges: HTMLElement;
  private readonly tags: HTMLElement;
  private readonly time: HTMLElement;
  /** The one line the panel shows when folded: model, level, faces. */
  private readonly summary: HTMLElement;

  /** Folded at first on narrow screens (a phone, a tablet upright), where the list would cover the model. */
  constructor(narrow = window.matchMedia('(max-width: 820px)').matches) {
    const list = el('dl', { className: 'facts' });
    const row = (key: string, label: string): HTMLElement => {
      const dd = el('dd', { testId: `facts.${key}`, text: '–' });
      list.append(el('dt', { text: label }), dd);
      return dd;
    };
    this.model = row('model', 'Model');
    this.level = row('level', 'Level');
    for (const { key, label } of ROWS) this.cells.set(key, row(key, label));
    this.controlEdges = row('control-edges', 'Control edges');
    this.tags = row('tags', 'Tags');
    this.time = row('time', 'Last step');
    this.summary = el('summary', { testId: 'facts.summary', className: 'facts-summary', text: 'Facts' });
    const details = el(
      'details',
      // data-covers-view: Fit keeps the model out from under it (render/fit.ts).
      {
        testId: 'facts',
        className: 'facts-panel',
        attrs: { 'aria-label': 'Facts of the shown level', 'data-covers-view': '' },
      },
      this.summary,
      list,
    );
    details.open = !narrow;
    this.element = details;
  }

  update(state: ViewerState): void {
    this.element.hidden = state.levelCount === 0;
    this.model.textContent = state.modelName ?? '–';
    this.model.title = state.modelName ?? '';
    this.level.textContent = state.levelCount > 0 ? String(state.level) : '–';
    for (const { key, value } of ROWS) {
      const cell = this.cells.get(key);
      if (cell) cell.textContent = state.facts ? value(state.facts) : '–';
    }
    const types = this.cells.get('face-types');
    if (types) types.title = state.facts ? `${faceTypes(state.facts)}: the faces by their number of sides` : '';
    this.controlEdges.textContent = state.facts ? controlEdges(state.facts, state.level) : '–';
    this.tags.textContent = tagText(state.tags);
    this.tags.title = state.tags?.notes.join('\n') ?? '';
    this.time.textContent = state.stepMs === null ? '–' : `${state.stepMs.toFixed(1)} ms`;
    this.summary.textContent = state.facts ? `Level ${state.level} · ${faceTypes(state.facts)}` : 'Facts';
  }
}
