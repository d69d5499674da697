/**
 * Page object of pages that embed SubdivLab: the teaching example and test
 * pages served through `page.route` (they are not shipped). It reads the
 * elements' properties and the events they fired, recorded from the start
 * by an init script.
 */
import { expect, type Page } from '@playwright/test';
import type { MeshFacts } from '../../web/core/mesh';

export interface RecordedEvent {
  type: string;
  /** id of the element that fired it ('' for the iframe's messages). */
  id: string;
  detail: Record<string, unknown>;
}

export interface ViewerReading {
  level: number;
  facts: MeshFacts | null;
  started: boolean;
  gpuReleased: boolean;
  levelsAttribute: string | null;
}

declare global {
  interface Window {
    __events?: RecordedEvent[];
    /**
     * Resolves with the progress label once `element` has a step under way (its first
     * progress event of kind 'subdivide'): a test acts during a step without a fixed
     * wait, which a fast step can beat.
     */
    __stepUnderWay?: (element: HTMLElement) => Promise<string>;
  }
}

/** A test page that loads the element from the app's dist/embed/ (served one folder down), with `css` and `body`. */
export function viewerPage(title: string, css: string, body: string): string {
  return `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>${title}</title>
<script type="module" src="../embed/subdiv-viewer.js"></script>
<style>${css}</style></head><body>
${body}
</body></html>`;
}

export class EmbedPage {
  constructor(readonly page: Page) {}

  /** Records every element event and every message from an iframe, from the first script on. */
  async recordEvents(): Promise<void> {
    await this.page.addInitScript(() => {
      window.__stepUnderWay = (element) =>
        new Promise<string>((resolve) => {
          const onProgress = (event: Event) => {
            const detail = (event as CustomEvent<{ busy: boolean; kind: string | null; label: string }>).detail;
            if (!detail.busy || detail.kind !== 'subdivide') return;
            element.removeEventListener('progress', onProgress);
            resolve(detail.label);
          };
          element.addEventListener('progress', onProgress);
        });
      window.__events = [];
      for (const type of ['load', 'level-change', 'error', 'progress', 'stencil', 'basis', 'distance']) {
        document.addEventListener(type, (event) => {
          const target = event.target as HTMLElement;
          const detail = (event as CustomEvent).detail;
          window.__events?.push({ type, id: target.id, detail: JSON.parse(JSON.stringify(detail)) });
        });
      }
      window.addEventListener('message', (event) => {
        const data = event.data as { subdivlab?: string };
        if (data && typeof data.subdivlab === 'string') {
          window.__events?.push({
            type: `message:${data.subdivlab}`,
            id: '',
            detail: JSON.parse(JSON.stringify(data)),
          });
        }
      });
    });
  }

  /** Serves `html` at `path` under the app's origin (test pages are not part of the build). */
  async serve(path: string, html: string): Promise<void> {
    await this.page.route(`**/${path}`, (route) => route.fulfill({ body: html, contentType: 'text/html' }));
  }

  async events(type?: string, id?: string): Promise<RecordedEvent[]> {
    const all = await this.page.evaluate(() => window.__events ?? []);
    return all.filter((e) => (type === undefined || e.type === type) && (id === undefined || e.id === id));
  }

  /** The last `level-change` of element `id`. */
  async lastLevelChange(id: string): Promise<RecordedEvent | undefined> {
    return (await this.events('level-change', id)).at(-1);
  }

  async reading(id: string): Promise<ViewerReading> {
    return this.page.evaluate((elementId) => {
      const e = document.getElementById(elementId) as HTMLElementTagNameMap['subdiv-viewer'];
      return {
        level: e.level,
        facts: e.facts,
        started: e.state !== null,
        gpuReleased: e.gpuReleased,
        levelsAttribute: e.getAttribute('levels'),
      };
    }, id);
  }

  /** Waits until element `id` shows `level` and is idle. */
  async waitForLevel(id: string, level: number): Promise<ViewerReading> {
    await expect
      .poll(async () => {
        const r = await this.reading(id);
        const busy = await this.page.evaluate(
          (elementId) => (document.getElementById(elementId) as HTMLElementTagNameMap['subdiv-viewer']).state?.busy,
          id,
        );
        return r.level === level && !busy;
      })
      .toBe(true);
    return this.reading(id);
  }

  /** The text of element `id`'s caption `part` (the teaching tool's, or `distance`) as shown, a line a row; '' while hidden. */
  async caption(id: string, partName = 'tool'): Promise<string> {
    const part = this.page.locator(`#${id}`).locator(`[part="${partName}"]`);
    if (!(await part.isVisible())) return '';
    const texts = await part
      .locator('.tool-line:visible, .tool-legend:visible span, .tool-note:visible')
      .allTextContents();
    return texts.join('\n');
  }

  /** Screenshot of the page into test-results/screenshots/ (looked at by people, not compared). */
  async snapshot(name: string, fullPage = false): Promise<void> {
    await this.page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    await this.page.screenshot({ path: `test-results/screenshots/${name}.png`, fullPage });
  }
}
