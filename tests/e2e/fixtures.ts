/**
 * The `app` fixture (a SubdivLabPage) and a guard that fails a test on any
 * console error or uncaught page error. A test that expects a console error
 * (e.g. a 404 it provokes) lists a pattern in `allowedConsoleErrors`.
 */
import { test as base, expect } from '@playwright/test';
import { SubdivLabPage } from './subdivlab-page';

interface Fixtures {
  app: SubdivLabPage;
  allowedConsoleErrors: RegExp[];
}

export const test = base.extend<Fixtures>({
  allowedConsoleErrors: [[], { option: true }],
  app: async ({ page, allowedConsoleErrors }, use) => {
    const errors: string[] = [];
    page.on('console', (message) => {
      if (message.type() !== 'error') return;
      const text = message.text();
      if (!allowedConsoleErrors.some((pattern) => pattern.test(text))) errors.push(text);
    });
    page.on('pageerror', (error) => errors.push(`page error: ${error.message}`));
    await use(new SubdivLabPage(page));
    expect(errors, 'console errors').toEqual([]);
  },
});

export { expect };
