/**
 * Rules panel of the `custom` scheme: a preset menu (public/rules/*.json),
 * the refinement host, every weight of the rule set as a text field (a
 * number or a formula in n, k, j), a live check, Apply, Save rules… and
 * Load rules…. Formulas are parsed by web/core/expression.ts (never eval);
 * the rule set is judged by rule-set.ts's parseRuleSet and then by the
 * core itself (the `check` handler), so the panel shows the core's own
 * message for a weight that is not finite or a stencil that does not sum to 1.
 */
import {
  parseRuleSet,
  parseRuleSetText,
  RULE_PRESETS,
  type RuleHost,
  type RulePresetName,
  type RuleSet,
  ruleSetToText,
} from '../core/rule-set';
import { button, el, uniqueId } from './dom';
import { formulaError, getAt, ruleFileName, setAt, type WeightSpec, weightGroups, weightOf } from './rule-fields';
import { saveBlob } from './save-blob';

export interface RulesPanelHandlers {
  /** Judges a rule set as the core does (finite weights, stencils summing to 1); rejects with its message. */
  check: (rules: RuleSet) => Promise<void>;
  /** Uses `rules` for the custom scheme; `minLevel` is the level to recompute at least. */
  apply: (rules: RuleSet, minLevel: number) => void | Promise<void>;
}

/** Labels of the presets, in menu order. */
const PRESET_LABELS: Record<RulePresetName, string> = {
  'catmull-clark': 'Catmull-Clark',
  loop: 'Loop',
  'doo-sabin': 'Doo-Sabin',
  sqrt3: '√3 (Kobbelt)',
  'improved-loop': 'Improved Loop',
  linear: 'Linear',
};

/** What the panel says about each host. */
const HOSTS: Record<RuleHost, string> = {
  pqq: 'PQQ — primal quad quadrisection (Catmull-Clark-like); any polygons',
  ptq: 'PTQ — primal triangle quadrisection (Loop-like); needs triangles',
  dqq: 'DQQ — dual quad quadrisection (Doo-Sabin-like); any polygons',
  sqrt3: '√3 — Kobbelt’s triangle trisection with edge flips; needs triangles',
};

interface Field extends WeightSpec {
  input: HTMLInputElement;
  group: string;
}

type CheckState = 'checking' | 'valid' | 'invalid';

export class RulesPanel {
  readonly element: HTMLDetailsElement;
  private readonly preset: HTMLSelectElement;
  /** The menu's entry for rules that are no preset: a file's, or an edited preset. */
  private readonly other: HTMLOptionElement;
  private readonly name: HTMLInputElement;
  private readonly host: HTMLElement;
  private readonly description: HTMLElement;
  private readonly about: HTMLDetailsElement;
  private readonly weights: HTMLElement;
  private readonly status: HTMLElement;
  private readonly error: HTMLElement;
  private readonly applyButton: HTMLButtonElement;
  private readonly saveButton: HTMLButtonElement;
  private readonly fileInput: HTMLInputElement;
  private fields: Field[] = [];
  /** The rule set the fields were built from (its shape; the fields hold the values). */
  private base: RuleSet | null = null;
  /** Text of the rule set last applied (to say whether the fields differ). */
  private appliedText: string | null = null;
  private checkState: CheckState = 'invalid';
  private checkRun = 0;
  private checkTimer: ReturnType<typeof setTimeout> | undefined;
  private loading: Promise<void> | null = null;

  constructor(private readonly handlers: RulesPanelHandlers) {
    const presetId = uniqueId('rules-preset');
    this.preset = el('select', { testId: 'rules.preset', attrs: { id: presetId } });
    for (const name of RULE_PRESETS) {
      this.preset.append(el('option', { text: PRESET_LABELS[name], attrs: { value: name } }));
    }
    this.other = el('option', { attrs: { value: '' } });
    this.other.disabled = true;
    this.other.hidden = true;
    this.preset.append(this.other);
    this.preset.addEventListener('change', () => {
      if (this.preset.value) void this.loadPreset(this.preset.value as RulePresetName);
    });
    const nameId = uniqueId('rules-name');
    this.name = el('input', {
      testId: 'rules.name',
      attrs: { id: nameId, type: 'text', autocomplete: 'off', spellcheck: 'false' },
    });
    this.name.addEventListener('input', () => this.edited());
    this.host = el('output', { testId: 'rules.host', className: 'rules-host' });
    this.description = el('p', { testId: 'rules.description', className: 'hint' });
    // The file's own description can be long: one click away.
    this.about = el(
      'details',
      { className: 'rules-about' },
      el('summary', { text: 'About this rule set' }),
      this.description,
    );
    this.weights = el('div', { className: 'rules-weights' });
    const errorId = uniqueId('rules-error');
    this.error = el('p', { testId: 'rules.error', className: 'rules-error', attrs: { role: 'alert', id: errorId } });
    this.error.hidden = true;
    this.status = el('p', { testId: 'rules.status', className: 'hint', attrs: { 'aria-live': 'polite' } });
    this.applyButton = el('button', {
      testId: 'rules.apply',
      text: 'Apply',
      attrs: { type: 'submit', title: 'Recompute the levels up to the shown one (at least 1) with these weights' },
    });
    this.saveButton = button('Save rules…', 'rules.save', () => this.save(), 'Download these rules as a JSON file');
    this.fileInput = el('input', {
      testId: 'rules.load.input',
      attrs: { type: 'file', accept: '.json,application/json', 'aria-label': 'Load a rule file' },
    });
    this.fileInput.hidden = true;
    this.fileInput.addEventListener('change', () => {
      const file = this.fileInput.files?.[0];
      this.fileInput.value = '';
      if (file) void this.loadFile(file);
    });
    const load = button('Load rules…', 'rules.load', () => this.fileInput.click(), 'Open a rule file (JSON)');

    const form = el(
      'form',
      { className: 'rules-form', attrs: { 'aria-label': 'Custom rules', novalidate: '' } },
      el('label', { attrs: { for: presetId }, text: 'Preset' }),
      this.preset,
      el('label', { attrs: { for: nameId }, text: 'Name' }),
      this.name,
      el('p', { className: 'rules-host-line' }, 'Host: ', this.host),
      this.about,
      el('p', {
        className: 'hint',
        text: 'Numbers or formulas in n (valence), k (face degree), j (corner) with + − * / ^ ( ) pi cos sin sqrt.',
      }),
      this.weights,
      this.error,
      this.status,
      el('div', { className: 'row wrap' }, this.applyButton, this.saveButton, load, this.fileInput),
    );
    form.addEventListener('submit', (event) => {
      event.preventDefault();
      void this.applyDraft();
    });
    // Enter in a field applies too, also while the live check runs (the
    // browser's implicit submission would skip a form whose Apply is off).
    form.addEventListener('keydown', (event) => {
      if (event.key !== 'Enter' || !(event.target instanceof HTMLInputElement)) return;
      event.preventDefault();
      void this.applyDraft();
    });
    this.element = el(
      'details',
      { testId: 'rules', className: 'panel rules-panel' },
      el('summary', { testId: 'rules.toggle' }, el('h2', { text: 'Rules' })),
      form,
    );
    this.element.open = true;
    this.updateButtons();
  }

  /** Loads and applies the first preset unless rules are applied; resolves when done (or failed: see rules.error). */
  ensureRules(): Promise<void> {
    if (this.appliedText !== null) return Promise.resolve();
    this.loading ??= this.loadPreset(RULE_PRESETS[0]).finally(() => {
      this.loading = null;
    });
    return this.loading;
  }

  /** Fetches public/rules/NAME.json (relative to the page, so a sub-path works), shows and applies it. */
  async loadPreset(name: RulePresetName): Promise<void> {
    const path = `rules/${name}.json`;
    await this.loadFrom(path, { preset: name }, async () => {
      const response = await fetch(new URL(path, document.baseURI));
      if (!response.ok) throw new Error(`HTTP ${response.status} ${response.statusText}`.trim());
      return response.text();
    });
  }

  /** Reads a rule file; a bad file leaves the current rules as they are and says why. */
  async loadFile(file: File): Promise<void> {
    await this.loadFrom(file.name, { file: file.name }, () => file.text());
  }

  private async loadFrom(
    source: string,
    origin: { preset: RulePresetName } | { file: string },
    read: () => Promise<string>,
  ): Promise<void> {
    const previous = this.preset.value;
    let rules: RuleSet;
    try {
      rules = parseRuleSetText(await read());
      await this.handlers.check(rules);
    } catch (error) {
      this.preset.value = previous;
      this.showError(`${source}: ${messageOf(error)}`);
      return;
    }
    this.show(rules);
    if ('file' in origin) this.showOther(`From file: ${origin.file}`);
    else {
      this.other.hidden = true;
      this.preset.value = origin.preset;
    }
    this.setCheck('valid', null);
    await this.apply(rules, 0);
  }

  /** Builds the fields for `rules`. */
  private show(rules: RuleSet): void {
    // A check of the old fields that is still running or waiting must not judge the new ones.
    clearTimeout(this.checkTimer);
    this.checkRun++;
    this.base = structuredClone(rules);
    this.name.value = rules.name ?? '';
    this.host.textContent = HOSTS[rules.host];
    this.description.textContent = rules.description ?? '';
    this.about.hidden = !rules.description;
    this.fields = [];
    const sets = weightGroups(rules).map(({ key, legend, specs, columns }) => {
      const rows = specs.map((spec) => {
        const id = uniqueId('rules-weight');
        const value = getAt(rules, spec.path);
        const input = el('input', {
          testId: `rules.weight.${spec.path.join('.')}`,
          attrs: {
            id,
            type: 'text',
            inputmode: 'text',
            autocomplete: 'off',
            spellcheck: 'false',
            'aria-label': `${legend}: ${spec.label}`,
          },
        });
        input.value = String(value);
        input.title = input.value;
        input.addEventListener('input', () => {
          input.title = input.value;
          this.edited();
        });
        this.fields.push({ ...spec, input, group: key });
        return el('div', { className: 'rules-weight' }, el('label', { attrs: { for: id }, text: spec.label }), input);
      });
      const group = el(
        'fieldset',
        { className: columns ? 'rules-group columns' : 'rules-group', attrs: { 'data-group': key } },
        el('legend', { text: legend }),
        ...rows,
      );
      // Four weights (the border edge rule) as 2 × 2, so each field keeps some width. Set through
      // the CSSOM: the site's policy refuses style attributes.
      group.style.setProperty('--columns', String(specs.length === 4 ? 2 : specs.length));
      return group;
    });
    const omitted =
      rules.border === undefined
        ? [el('p', { className: 'hint', text: 'Border: the host’s default rule (not part of this rule set).' })]
        : [];
    this.weights.replaceChildren(...sets, ...omitted);
  }

  /** The rule set the fields describe (not yet checked). */
  private draft(): RuleSet {
    const rules = structuredClone(this.base) as RuleSet;
    const name = this.name.value.trim();
    if (name) rules.name = name;
    else delete rules.name;
    for (const field of this.fields) setAt(rules, field.path, weightOf(field.input.value));
    return rules;
  }

  /** The draft as a rule file's text, or null when rule-set.ts refuses it. */
  private draftText(): string | null {
    try {
      return ruleSetToText(parseRuleSet(this.draft()));
    } catch {
      return null;
    }
  }

  /** A field changed: the menu no longer shows a preset as it is (choosing it again restores it). */
  private edited(): void {
    const preset = this.preset.value as RulePresetName | '';
    if (preset) this.showOther(`${PRESET_LABELS[preset]} (edited)`);
    this.scheduleCheck();
  }

  private showOther(label: string): void {
    this.other.textContent = label;
    this.other.hidden = false;
    this.preset.value = '';
  }

  private scheduleCheck(): void {
    this.setCheck('checking', null);
    clearTimeout(this.checkTimer);
    this.checkTimer = setTimeout(() => void this.check(), 150);
  }

  /** The live check: each formula, then rule-set.ts, then the core. Resolves the rules when valid. */
  private async check(): Promise<RuleSet | null> {
    clearTimeout(this.checkTimer);
    if (!this.base) return null;
    const run = ++this.checkRun;
    for (const group of this.weights.querySelectorAll('fieldset')) group.classList.remove('invalid');
    let firstBad: { field: Field; message: string } | null = null;
    for (const field of this.fields) {
      const message = formulaError(field.input.value, field.vars);
      field.input.setAttribute('aria-invalid', String(message !== null));
      if (message) field.input.setAttribute('aria-describedby', this.error.id);
      else field.input.removeAttribute('aria-describedby');
      if (message && !firstBad) firstBad = { field, message };
    }
    if (firstBad) {
      this.setCheck('invalid', `${firstBad.field.input.getAttribute('aria-label')}: ${firstBad.message}`);
      return null;
    }
    let rules: RuleSet;
    try {
      rules = parseRuleSet(this.draft());
      await this.handlers.check(rules);
    } catch (error) {
      if (run !== this.checkRun) return null;
      const message = messageOf(error);
      this.markGroup(message);
      this.setCheck('invalid', message);
      return null;
    }
    if (run !== this.checkRun) return null;
    this.setCheck('valid', null);
    return rules;
  }

  /** Outlines the group a core message names ("the edge rule sums to 1.05, not 1"). */
  private markGroup(message: string): void {
    const group = /the (border vertex|border edge|border corner|vertex|edge|corner) rule/.exec(message)?.[1];
    if (group) this.weights.querySelector(`fieldset[data-group="${group}"]`)?.classList.add('invalid');
  }

  private async applyDraft(): Promise<void> {
    const rules = await this.check();
    if (!rules) {
      this.fields.find((f) => f.input.getAttribute('aria-invalid') === 'true')?.input.focus();
      return;
    }
    await this.apply(rules, 1);
  }

  private async apply(rules: RuleSet, minLevel: number): Promise<void> {
    this.appliedText = ruleSetToText(rules);
    this.updateButtons();
    await this.handlers.apply(rules, minLevel);
  }

  private save(): void {
    if (this.checkState !== 'valid' || !this.base) return;
    const rules = parseRuleSet(this.draft());
    saveBlob(new Blob([ruleSetToText(rules)], { type: 'application/json' }), ruleFileName(rules));
  }

  private setCheck(state: CheckState, message: string | null): void {
    this.checkState = state;
    if (message) this.showError(message);
    else this.error.hidden = true;
    this.updateButtons();
  }

  private showError(message: string): void {
    this.error.textContent = message;
    this.error.hidden = false;
    this.updateButtons();
  }

  private updateButtons(): void {
    const valid = this.checkState === 'valid' && this.base !== null;
    this.applyButton.disabled = !valid;
    this.saveButton.disabled = !valid;
    const pending = this.base !== null && this.appliedText !== this.draftText();
    this.status.textContent = !this.base
      ? 'Loading the rules…'
      : this.checkState === 'checking'
        ? 'Checking…'
        : this.checkState === 'invalid'
          ? 'Not applied: fix the weight named above.'
          : pending
            ? 'Every stencil sums to 1. Press Apply to use these weights.'
            : 'These rules are applied.';
  }
}

function messageOf(error: unknown): string {
  return error instanceof Error ? error.message : String(error);
}
