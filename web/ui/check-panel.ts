/**
 * Check a result panel: a student's OFF/OBJ file, the level it claims and a
 * tolerance; then the verdict, its reasons, the errors and the worst
 * vertices, each with a button that shows its expected stencil.
 */
import type { ReadFormat } from '../core/mesh';
import { vertexName } from '../core/vertex-lines';
import type { CheckState } from '../teach/result-check';
import { detectFormat } from '../viewer/mesh-source';
import { button, el, section, uniqueId } from './dom';

export interface CheckPanelHandlers {
  onCheck: (name: string, text: string | Uint8Array, format: ReadFormat, level: number, tolerance: number) => void;
  /** Shows the expected stencil of reference vertex `vertex` of level `level`. */
  onShowStencil: (level: number, vertex: number) => void;
}

function number(x: number): string {
  return x === 0 ? '0' : x.toPrecision(3);
}

export class CheckPanel {
  readonly element: HTMLElement;
  private readonly file: HTMLInputElement;
  private readonly level: HTMLInputElement;
  private readonly tolerance: HTMLInputElement;
  private readonly run: HTMLButtonElement;
  private readonly report: HTMLElement;

  constructor(handlers: CheckPanelHandlers) {
    const fileId = uniqueId('check-file');
    const levelId = uniqueId('check-level');
    const toleranceId = uniqueId('check-tolerance');
    this.file = el('input', {
      testId: 'check.file',
      attrs: { id: fileId, type: 'file', accept: '.off,.obj,.ply,.stl,text/plain' },
    });
    this.level = el('input', {
      testId: 'check.level',
      attrs: { id: levelId, type: 'number', min: '1', max: '8', step: '1', value: '1' },
    });
    this.tolerance = el('input', {
      testId: 'check.tolerance',
      attrs: { id: toleranceId, type: 'text', value: '1e-6' },
    });
    this.run = button('Check', 'check.run', () => void this.submit(handlers), 'Compare the file with this level');
    this.report = el('div', { testId: 'check.report', attrs: { 'aria-live': 'polite' } });
    this.element = section(
      'Check a result',
      'check-panel',
      el('p', {
        className: 'hint',
        text: "Your program's level of this model and scheme, as OFF, OBJ, PLY or STL: it is read here and sent nowhere.",
      }),
      el('label', { attrs: { for: fileId }, text: 'Result file' }),
      this.file,
      el(
        'div',
        { className: 'row' },
        el('label', { attrs: { for: levelId }, text: 'Level' }),
        this.level,
        el('label', { attrs: { for: toleranceId }, text: 'Tolerance' }),
        this.tolerance,
      ),
      this.run,
      this.report,
    );
    this.report.addEventListener('click', (event) => {
      const target = (event.target as HTMLElement).closest('button');
      if (target?.dataset.vertex) handlers.onShowStencil(Number(target.dataset.level), Number(target.dataset.vertex));
    });
  }

  private async submit(handlers: CheckPanelHandlers): Promise<void> {
    const file = this.file.files?.[0];
    const level = Number(this.level.value);
    const tolerance = Number(this.tolerance.value);
    if (!file) return this.say('Choose the result file first.');
    if (!Number.isInteger(level) || level < 1) return this.say('The level is a whole number, 1 or more.');
    if (!(tolerance >= 0)) return this.say('The tolerance is a number, 0 or more (a share of the diagonal).');
    // Read as bytes: PLY and STL may be binary; the format from the extension, else from the content.
    handlers.onCheck(file.name, new Uint8Array(await file.arrayBuffer()), detectFormat(file.name), level, tolerance);
  }

  private say(text: string): void {
    this.report.replaceChildren(el('p', { testId: 'check.verdict', className: 'hint', text }));
  }

  update(state: CheckState): void {
    this.run.disabled = !state.available;
    const checked = state.checked;
    if (!checked) {
      if (this.report.querySelector('[data-testid="check.summary"]')) this.report.replaceChildren();
      return;
    }
    const c = checked.comparison;
    if (this.report.dataset.shown === `${checked.name}/${checked.level}/${c.maxError}/${c.match}`) return;
    this.report.dataset.shown = `${checked.name}/${checked.level}/${c.maxError}/${c.match}`;
    const percent = c.diagonal > 0 ? ` (${number((100 * c.maxError) / c.diagonal)} % of the diagonal)` : '';
    this.report.replaceChildren(
      el('p', {
        testId: 'check.verdict',
        className: c.match ? 'verdict match' : 'verdict mismatch',
        text: c.match
          ? `✓ ${checked.name} is level ${checked.level}.`
          : `✗ ${checked.name} is not level ${checked.level}.`,
      }),
      ...(c.reasons.length > 0
        ? [el('ul', { testId: 'check.reasons' }, ...c.reasons.map((r) => el('li', { text: r })))]
        : []),
      el('p', {
        testId: 'check.summary',
        text:
          `Largest error ${number(c.maxError)}${percent}, mean ${number(c.meanError)}; ` +
          `tolerance ${number(c.tolerance)}; vertices matched ${c.matching === 'order' ? 'in order' : 'to the nearest'}.` +
          (c.maxError > c.tolerance
            ? ' On the surface: dark where your points are right, yellow where they are farthest.'
            : ''),
      }),
      el(
        'ol',
        { testId: 'check.worst', className: 'check-worst' },
        ...c.worst
          .filter((w) => w.error > c.tolerance)
          .map((w) =>
            el(
              'li',
              {},
              `Your ${vertexName(w, c.fileFormat)}: ${number(w.error)} off `,
              el('button', {
                text: 'its stencil',
                attrs: {
                  type: 'button',
                  'data-level': String(checked.level),
                  'data-vertex': String(w.reference),
                  title: `The stencil of level ${checked.level}'s vertex ${w.reference}, where it should be`,
                },
              }),
            ),
          ),
      ),
    );
  }
}
