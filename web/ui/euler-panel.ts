/**
 * The Euler operators part of the halfedges panel: CGAL's operators on the
 * picked halfedge (split_face with a second pick), Undo, what the last one
 * left (V, E, F, χ and CGAL's validity), and the √3 by hand walk-through
 * (Step, Play / Pause, its progress and, at the end, the verdict of the
 * comparison with the √3 scheme's level 1).
 */
import type { EulerOperator } from '../core/halfedges';
import type { EulerState } from '../teach/euler-steps';
import { button, el } from './dom';

export interface EulerPanelHandlers {
  onChooseSecond: (on: boolean) => void;
  onOperator: (op: EulerOperator) => void;
  onUndo: () => void;
  onStep: () => void;
  onPlay: (play: boolean) => void;
}

const OPERATORS: readonly { op: EulerOperator; label: string; title: string }[] = [
  {
    op: 'split_face',
    label: 'Split face',
    title: 'split_face(h, g, m): a new edge from the target of h to the target of g, both on one face',
  },
  { op: 'join_face', label: 'Join faces', title: "join_face(h, m): removes h's edge, joining its two faces" },
  {
    op: 'add_center_vertex',
    label: 'Add centre vertex',
    title: "add_center_vertex(h, m): a vertex in h's face joined to each corner",
  },
  {
    op: 'remove_center_vertex',
    label: 'Remove centre vertex',
    title: "remove_center_vertex(h, m): removes h's target and its edges, one face left",
  },
  { op: 'split_edge', label: 'Split edge', title: "split_edge(h, m): a vertex in the middle of h's edge" },
  { op: 'flip_edge', label: 'Flip edge', title: "flip_edge(h, m): the other diagonal of h's two triangles" },
];

export class EulerPanel {
  readonly element: HTMLElement;
  private readonly second: HTMLButtonElement;
  private readonly operators: HTMLButtonElement[];
  private readonly undo: HTMLButtonElement;
  private readonly outcome: HTMLElement;
  private readonly problem: HTMLElement;
  private readonly step: HTMLButtonElement;
  private readonly play: HTMLButtonElement;
  private readonly progress: HTMLElement;
  private readonly verdict: HTMLElement;
  private choosing = false;
  private playing = false;

  constructor(handlers: EulerPanelHandlers) {
    this.second = button(
      'Second halfedge…',
      'euler.second',
      () => handlers.onChooseSecond(!this.choosing),
      'For Split face: the next click (or number) picks a second halfedge of the same face',
    );
    this.operators = OPERATORS.map(({ op, label, title }) =>
      button(label, `euler.${op}`, () => handlers.onOperator(op), title),
    );
    this.undo = button('Undo', 'euler.undo', handlers.onUndo, 'Show the mesh before the last operator again');
    this.outcome = el('p', { testId: 'euler.outcome', attrs: { 'aria-live': 'polite' } });
    this.problem = el('p', { testId: 'euler.problem', className: 'rules-error', attrs: { role: 'alert' } });
    this.step = button('Step', 'sqrt3.step', handlers.onStep, 'Apply the next operator of one √3 step');
    this.play = button('Play', 'sqrt3.play', () => handlers.onPlay(!this.playing), 'Apply the operators one by one');
    this.progress = el('p', { testId: 'sqrt3.progress' });
    this.verdict = el('p', { testId: 'sqrt3.verdict', attrs: { 'aria-live': 'polite' } });
    this.element = el(
      'div',
      { testId: 'euler' },
      el('h3', { text: 'Euler operators' }),
      el('p', {
        className: 'hint',
        text: "On the picked halfedge (red). Each edit becomes the model's level 0: levels are computed from the edited mesh.",
      }),
      el(
        'div',
        { className: 'row wrap', attrs: { role: 'group', 'aria-label': 'Euler operators' } },
        this.second,
        ...this.operators,
      ),
      el('div', { className: 'row' }, this.undo),
      this.outcome,
      this.problem,
      el('h3', { text: '√3 by hand' }),
      el('p', {
        className: 'hint',
        text: 'One √3 step as the tutorial writes it, on a closed triangle mesh: a centre vertex per face, a flip per old edge, then the old vertices smoothed.',
      }),
      el('div', { className: 'row' }, this.step, this.play),
      this.progress,
      this.verdict,
    );
  }

  /** `picked`: a halfedge is picked; `choosing`: the next pick is split_face's second; `second`: it, when picked. */
  update(state: EulerState, picked: boolean, choosing: boolean, second: number | null): void {
    this.choosing = choosing;
    this.second.disabled = !picked;
    this.second.setAttribute('aria-pressed', String(choosing));
    this.second.textContent = second !== null ? `Second halfedge: ${second}` : 'Second halfedge…';
    for (const b of this.operators) b.disabled = !state.available;
    this.undo.disabled = !state.canUndo;
    const o = state.outcome;
    this.outcome.textContent = o
      ? `${o.what === 'undo' ? 'Undone' : o.what}: V ${o.facts.vertices}, E ${o.facts.edges}, F ${o.facts.faces}, ` +
        `χ = ${o.facts.eulerCharacteristic}; CGAL's is_valid_polygon_mesh: ` +
        `${o.valid === null ? 'not run (the model as loaded)' : o.valid ? 'valid' : 'NOT valid'}.`
      : '';
    this.problem.textContent = state.problem;
    this.problem.hidden = state.problem === '';
    const w = state.walk;
    this.playing = w?.playing ?? false;
    this.play.textContent = this.playing ? 'Pause' : 'Play';
    this.play.setAttribute('aria-pressed', String(this.playing));
    this.step.disabled = this.playing;
    this.progress.textContent = w ? `${w.done} / ${w.total} operators${w.last ? `; last: ${w.last}` : ''}` : '';
    this.verdict.textContent = w?.verdict ?? '';
  }
}
