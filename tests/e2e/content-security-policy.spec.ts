/**
 * The built site's Content-Security-Policy (web/site/content-security-policy.ts):
 * every page declares it before anything it governs, the browser enforces it
 * (an inline script or style is refused), and what the app does needs
 * nothing it refuses — every other e2e test runs under it too, and a refusal
 * is a console error, which fails them.
 */
import { readFileSync } from 'node:fs';
import { CONTENT_SECURITY_POLICY } from '../../web/site/content-security-policy';
import { expect, test } from './fixtures';

const DIST = process.env.SUBDIVLAB_E2E_DIST ?? 'dist';
const PAGES = ['index.html', 'embed.html', 'examples/index.html'].map((page) => `${DIST}/${page}`);

test('each built page declares the policy first, and has no inline script, style element or style attribute', () => {
  for (const path of PAGES) {
    const html = readFileSync(path, 'utf8');
    const declared = /<meta http-equiv="Content-Security-Policy" content="([^"]*)"/.exec(html);
    expect(declared?.[1], path).toBe(CONTENT_SECURITY_POLICY);
    const at = html.indexOf('Content-Security-Policy');
    expect(html.search(/<script|<link rel="(stylesheet|modulepreload)"/), path).toBeGreaterThan(at);
    expect(html.match(/<script(?![^>]*\bsrc=)[^>]*>/g) ?? [], path).toEqual([]);
    expect(html.match(/<style|\sstyle="/g) ?? [], path).toEqual([]);
  }
});

test.describe('the browser enforces it', () => {
  test.use({
    allowedConsoleErrors: [
      /^(Executing inline script|Applying inline style) violates the following Content Security Policy/,
    ],
  });

  test('an inline script and a style attribute are refused in the app, which works without them', async ({ app }) => {
    await app.open();
    const refused = await app.page.evaluate(async () => {
      const seen: string[] = [];
      document.addEventListener('securitypolicyviolation', (event) => seen.push(event.effectiveDirective));
      const script = document.createElement('script');
      script.textContent = 'window.inlineRan = true;';
      document.body.append(script);
      const probe = document.createElement('div');
      probe.setAttribute('style', 'width: 123px');
      document.body.append(probe);
      const width = getComputedStyle(probe).width;
      probe.remove();
      await new Promise((resolve) => setTimeout(resolve, 100));
      return { seen, ran: (window as { inlineRan?: boolean }).inlineRan === true, width };
    });
    expect(refused.ran).toBe(false);
    expect(refused.width).not.toBe('123px');
    expect(refused.seen).toEqual(expect.arrayContaining(['script-src-elem', 'style-src-attr']));
  });
});

test('under the policy: the core compiles and subdivides, and styles set through the CSSOM apply', async ({ app }) => {
  await app.open();
  const violations = await app.page.evaluate(() => {
    const seen: string[] = [];
    document.addEventListener('securitypolicyviolation', (event) =>
      seen.push(`${event.effectiveDirective} ${event.blockedURI}`),
    );
    return seen;
  });
  expect(violations).toEqual([]);
  await app.openSample('cube', 'cube.off');
  await app.subdivide();
  expect((await app.facts()).faces).toBe(24);
  await test.step('the rules panel lays out the border rule’s four weights as 2 × 2 (a CSS variable)', async () => {
    await app.chooseScheme('custom');
    const columns = await app.page
      .locator('fieldset.rules-group')
      .evaluateAll((groups) => groups.map((g) => getComputedStyle(g).getPropertyValue('--columns').trim()));
    expect(columns.length).toBeGreaterThan(0);
    expect(columns.every((c) => /^[1-9]$/.test(c))).toBe(true);
  });
});

test('the element’s shadow styles apply on a page under the policy (a constructed style sheet)', async ({ page }) => {
  await page.goto('./embed.html?src=meshes/cube.off&levels=1');
  const viewer = page.locator('subdiv-viewer');
  await expect.poll(() => viewer.evaluate((v: HTMLElementTagNameMap['subdiv-viewer']) => v.level)).toBe(1);
  const styles = await viewer.evaluate((v) => {
    const frame = v.shadowRoot?.querySelector('.frame');
    return {
      sheets: v.shadowRoot?.adoptedStyleSheets.length ?? 0,
      styleElements: v.shadowRoot?.querySelectorAll('style').length ?? -1,
      position: frame ? getComputedStyle(frame).position : null,
    };
  });
  expect(styles).toEqual({ sheets: 1, styleElements: 0, position: 'absolute' });
});
