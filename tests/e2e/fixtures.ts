/**
 * The `app` fixture (a SubdivLabPage), the `embed` fixture (an EmbedPage,
 * for pages that embed the viewer) and a guard that fails a test on any
 * console error or uncaught page error. A test that expects a console error
 * (e.g. a 404 it provokes) lists a pattern in `allowedConsoleErrors`.
 */
import { test as base, expect, type Page } from '@playwright/test';
import { EmbedPage } from './embed-page';
import { SubdivLabPage } from './subdivlab-page';

interface Fixtures {
  app: SubdivLabPage;
  embed: EmbedPage;
  allowedConsoleErrors: RegExp[];
}

/** Runs `body` and then fails if the page logged an error not allowed by `allowed`. */
async function guardConsole(page: Page, allowed: RegExp[], body: () => Promise<void>): Promise<void> {
  const errors: string[] = [];
  page.on('console', (message) => {
    if (message.type() !== 'error') return;
    const text = message.text();
    if (!allowed.some((pattern) => pattern.test(text))) errors.push(text);
  });
  page.on('pageerror', (error) => errors.push(`page error: ${error.message}`));
  await body();
  expect(errors, 'console errors').toEqual([]);
}

export const test = base.extend<Fixtures>({
  allowedConsoleErrors: [[], { option: true }],
  app: async ({ page, allowedConsoleErrors }, use) => {
    await guardConsole(page, allowedConsoleErrors, () => use(new SubdivLabPage(page)));
  },
  embed: async ({ page, allowedConsoleErrors }, use) => {
    await guardConsole(page, allowedConsoleErrors, async () => {
      const embed = new EmbedPage(page);
      await embed.recordEvents();
      await use(embed);
    });
  },
});

export { expect };
