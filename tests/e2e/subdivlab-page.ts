/**
 * Page object of the SubdivLab app: acts as a user (drops files, clicks,
 * presses keys) and reads state through the typed test API on
 * window.__subdivlab.
 */
import { readFile } from 'node:fs/promises';
import { type Download, expect, type Locator, type Page, test } from '@playwright/test';
import type { SubdivLabTestState } from '../../web/app/test-api';

/** Counts shown in the facts panel. */
/** What the page showed when the progress box came up (SubdivLabPage.cancelWhenProgressShows). */
export interface ProgressSeen {
  label: string;
  busy: boolean;
  /** Milliseconds late a timer set for 0 ms ran. */
  lateMs: number;
}

export interface ShownFacts {
  vertices: number;
  edges: number;
  faces: number;
  components: number;
  boundaries: number;
  genus: number;
  faceTypes: string;
}

/** A link state with no model: the app opens empty (no first-visit sample). */
export const EMPTY_STATE = '#scheme=catmull-clark';

export class SubdivLabPage {
  constructor(readonly page: Page) {}

  byTestId(id: string): Locator {
    return this.page.getByTestId(id);
  }

  get canvas(): Locator {
    return this.page.locator('[data-testid="viewer"] canvas.subdiv-canvas');
  }

  get errorBanner(): Locator {
    return this.byTestId('error.banner');
  }

  /**
   * Opens the app at `./` + `query` and waits for the WASM core. The default
   * is a link state without a model (`#scheme=catmull-clark`): the app starts
   * empty, as the tests that drop their own file expect. A bare `./` is a first
   * visit, which loads a sample (see {@link openFirstVisit}).
   */
  async open(query = EMPTY_STATE): Promise<void> {
    await this.page.goto(`./${query}`);
    await this.page.waitForFunction(() => window.__subdivlab?.state().ready === true, undefined, { timeout: 30_000 });
  }

  /** Opens the app with no hash and no ?src= and waits until its sample is loaded and idle. */
  async openFirstVisit(): Promise<SubdivLabTestState> {
    await this.open('');
    await expect(this.byTestId('viewer.first-visit')).toBeVisible();
    return this.idle();
  }

  /** The page's URL hash, parsed (without the `#`). */
  async hashParams(): Promise<URLSearchParams> {
    return new URLSearchParams((await this.page.evaluate(() => window.location.hash)).replace(/^#/, ''));
  }

  /** Waits until the URL hash has `key` = `value` (the app writes it about 300 ms after a change). */
  async waitForHash(key: string, value: string): Promise<void> {
    await expect.poll(async () => (await this.hashParams()).get(key)).toBe(value);
  }

  async state(): Promise<SubdivLabTestState> {
    return this.page.evaluate(() => {
      const api = window.__subdivlab;
      if (!api) throw new Error('window.__subdivlab is missing');
      return api.state();
    });
  }

  /** Waits until no load or step runs. */
  async idle(): Promise<SubdivLabTestState> {
    await this.page.waitForFunction(() => window.__subdivlab?.state().busy === false);
    return this.state();
  }

  /**
   * Drags a file over the page and drops it, as the OS would: a DataTransfer
   * carrying the file's bytes, dispatched as dragenter, dragover and drop.
   * Checks that the drop target shows while dragging.
   */
  async dropFile(name: string, contents: string | Buffer): Promise<void> {
    await test.step(`drop ${name}`, async () => {
      // Text crosses as a string (fast for big meshes), anything else as bytes.
      const data = typeof contents === 'string' ? contents : [...contents];
      const transfer = await this.page.evaluateHandle(
        ({ name, data }) => {
          const dt = new DataTransfer();
          const part = typeof data === 'string' ? data : new Uint8Array(data);
          dt.items.add(new File([part], name, { type: 'application/octet-stream' }));
          return dt;
        },
        { name, data },
      );
      const target = this.page.locator('body');
      await target.dispatchEvent('dragenter', { dataTransfer: transfer });
      await target.dispatchEvent('dragover', { dataTransfer: transfer });
      await expect(this.byTestId('dropzone')).toBeVisible();
      await target.dispatchEvent('drop', { dataTransfer: transfer });
      await expect(this.byTestId('dropzone')).toBeHidden();
      await transfer.dispose();
    });
  }

  /** Drops a file from disk under its own name. */
  async dropPath(path: string, name = path.split('/').pop() ?? path): Promise<void> {
    await this.dropFile(name, await readFile(path));
  }

  /** Drops a file and waits until it is the loaded model. */
  async load(name: string, contents: string | Buffer): Promise<SubdivLabTestState> {
    await this.dropFile(name, contents);
    await expect(this.byTestId('facts.model')).toHaveText(name);
    return this.idle();
  }

  /** Picks `scheme` in the menu and waits until the shown level is computed with it. */
  async chooseScheme(scheme: string): Promise<SubdivLabTestState> {
    await this.byTestId('controls.scheme').selectOption(scheme);
    await expect.poll(async () => (await this.state()).scheme).toBe(scheme);
    return this.idle();
  }

  /** Presses Subdivide and waits for the next level to be shown. */
  async subdivide(): Promise<SubdivLabTestState> {
    const before = await this.state();
    await this.byTestId('controls.subdivide').click();
    await this.page.waitForFunction((n) => {
      const s = window.__subdivlab?.state();
      return s !== undefined && !s.busy && (s.levelCount > n || s.lastError !== null);
    }, before.levelCount);
    const after = await this.state();
    expect(after.lastError, 'subdivision failed').toBeNull();
    expect(after.level).toBe(before.levelCount);
    return after;
  }

  /**
   * Arms Cancel: the page itself presses the progress box's Cancel the moment
   * the box shows, and the returned promise resolves once it has, with what
   * the page showed then: the box's label, whether the app said it was busy,
   * and how late a timer set for 0 ms then ran (the main thread's answer
   * while the worker computes). A click from Playwright can come too late: a
   * step only a little longer than the box's 200 ms delay ends between the
   * box showing and the click.
   */
  async cancelWhenProgressShows(): Promise<() => Promise<ProgressSeen>> {
    await this.page.evaluate(() => {
      const flag = window as unknown as { cancelPressed?: ProgressSeen | null };
      flag.cancelPressed = null;
      const box = document.querySelector<HTMLElement>('[data-testid="progress"]');
      const cancel = document.querySelector<HTMLButtonElement>('[data-testid="progress.cancel"]');
      const label = document.querySelector<HTMLElement>('[data-testid="progress.label"]');
      if (!box || !cancel || !label) throw new Error('no progress box');
      const observer = new MutationObserver(() => {
        if (box.hidden) return;
        observer.disconnect();
        const seen = { label: label.textContent ?? '', busy: window.__subdivlab?.state().busy === true, lateMs: 0 };
        const set = performance.now();
        setTimeout(() => {
          seen.lateMs = performance.now() - set;
          cancel.click();
          flag.cancelPressed = seen;
        }, 0);
      });
      observer.observe(box, { attributes: true, attributeFilter: ['hidden'] });
    });
    return async () => {
      let seen: ProgressSeen | null = null;
      await expect
        .poll(async () => {
          seen = await this.page.evaluate(
            () => (window as unknown as { cancelPressed: ProgressSeen | null }).cancelPressed,
          );
          return seen !== null;
        })
        .toBe(true);
      return seen as unknown as ProgressSeen;
    };
  }

  /** Moves the level scrubber. */
  async scrubTo(level: number): Promise<void> {
    await this.byTestId('controls.level').fill(String(level));
    await expect.poll(async () => (await this.state()).level).toBe(level);
  }

  /** Reads the facts panel (text the user sees). */
  async facts(): Promise<ShownFacts> {
    const read = async (key: string) => (await this.byTestId(`facts.${key}`).textContent()) ?? '';
    // Counts are shown with thousands separators ("1,536").
    const num = async (key: string) => Number((await read(key)).replaceAll(',', ''));
    return {
      vertices: await num('vertices'),
      edges: await num('edges'),
      faces: await num('faces'),
      components: await num('components'),
      boundaries: await num('boundaries'),
      genus: await num('genus'),
      faceTypes: await read('face-types'),
    };
  }

  /** Pixels of the canvas as the compositor shows them (PNG bytes). */
  async canvasPixels(): Promise<Buffer> {
    // Let the on-demand render loop draw the latest state first.
    await this.page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    return this.canvas.screenshot();
  }

  /** Clicks `testId` and returns the download it starts. */
  async download(testId: string): Promise<Download> {
    const [download] = await Promise.all([this.page.waitForEvent('download'), this.byTestId(testId).click()]);
    return download;
  }

  /** Opens a sample from the gallery and waits until it is loaded. */
  async openSample(id: string, name: string): Promise<SubdivLabTestState> {
    await this.byTestId('gallery').locator('summary').click();
    await this.byTestId(`gallery.${id}`).click();
    await expect(this.byTestId('facts.model')).toHaveText(name);
    return this.idle();
  }

  /** Vertex positions of the shown level (x0 y0 z0 x1 ...), from the test API. */
  async positions(): Promise<number[]> {
    return this.page.evaluate(() => window.__subdivlab?.positions() ?? []);
  }

  /** The rules panel's field of the weight at `path` (`edge.end`, `vertex.self.6`, `border.vertex.0`). */
  weight(path: string): Locator {
    return this.byTestId(`rules.weight.${path}`);
  }

  /** Waits until the rules panel says its rules are applied and `level` is computed again (no step running). */
  async rulesApplied(level: number): Promise<SubdivLabTestState> {
    await expect(this.byTestId('rules.status')).toHaveText('These rules are applied.');
    // The status says "applied" as soon as the rules are taken; the levels follow after a
    // prediction round trip, so wait for the levels' own rules to be the applied ones.
    await this.page.waitForFunction((k) => {
      const s = window.__subdivlab?.state();
      if (s === undefined || s.busy) return false;
      const computed = JSON.stringify(s.levelRules) === JSON.stringify(s.customRules);
      return (s.level === k && computed) || s.lastError !== null;
    }, level);
    const state = await this.state();
    expect(state.lastError, 'recomputing with the rules failed').toBeNull();
    return state;
  }

  /** Picks a preset in the rules panel and waits until it is applied. */
  async chooseRulePreset(name: string, ruleName: string): Promise<SubdivLabTestState> {
    const { level } = await this.state();
    await this.byTestId('rules.preset').selectOption(name);
    await expect.poll(async () => (await this.state()).customRules?.name).toBe(ruleName);
    return this.rulesApplied(level);
  }

  /** Presses Apply in the rules panel (once the live check allows it) and waits for the recomputed levels. */
  async applyRules(): Promise<SubdivLabTestState> {
    const { level } = await this.state();
    await expect(this.byTestId('rules.apply')).toBeEnabled();
    await this.byTestId('rules.apply').click();
    return this.rulesApplied(Math.max(1, level));
  }

  /**
   * Screenshot of one panel into test-results/screenshots/NAME.png. The window
   * grows for the shot when the panel is taller than its scrolling column, then
   * gets its size back.
   */
  async panelSnapshot(testId: string, name: string): Promise<void> {
    const size = this.page.viewportSize() ?? { width: 1024, height: 700 };
    const panel = this.byTestId(testId);
    const height = await panel.evaluate((e) => e.scrollHeight);
    if (height + 200 > size.height) await this.page.setViewportSize({ width: size.width, height: height + 300 });
    await panel.scrollIntoViewIfNeeded();
    await this.page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    await panel.screenshot({ path: `test-results/screenshots/${name}.png` });
    await this.page.setViewportSize(size);
  }

  /** Screenshot of the page into test-results/ (looked at by people, not compared). */
  async snapshot(name: string): Promise<void> {
    await this.page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    await this.page.screenshot({ path: `test-results/screenshots/${name}.png` });
  }
}
