import { defineConfig } from '@playwright/test';

// End-to-end tests of the web app in Debian's Chromium, WebGL through
// SwiftShader. The server is a production build served by `vite preview`
// on a loopback port, unless SUBDIVLAB_E2E_URL points at a running one.
const port = Number(process.env.SUBDIVLAB_E2E_PORT ?? 4179);
const externalUrl = process.env.SUBDIVLAB_E2E_URL;
const baseURL = externalUrl ?? `http://127.0.0.1:${port}/`;
// The built site's folder (from the project's root): two runs side by side each build their own.
const dist = process.env.SUBDIVLAB_E2E_DIST ?? 'dist';

export default defineConfig({
  testDir: 'tests/e2e',
  outputDir: dist === 'dist' ? 'test-results/e2e' : `test-results/e2e-${dist.replace(/\W+/g, '-')}`,
  timeout: 60_000,
  expect: { timeout: 15_000 },
  // Two browsers, a spec file each at a time (the machines have 2 cores): the suite in 8.4 min
  // where one took 13.2, on a loaded machine; a file's tests stay in order.
  fullyParallel: false,
  workers: 2,
  retries: 0,
  reporter: [['list']],
  use: {
    baseURL,
    browserName: 'chromium',
    // Small canvases: SwiftShader draws on the CPU.
    viewport: { width: 1024, height: 700 },
    deviceScaleFactor: 1,
    acceptDownloads: true,
    trace: 'retain-on-failure',
    launchOptions: {
      executablePath: '/usr/bin/chromium',
      args: [
        '--no-sandbox',
        '--disable-background-networking',
        '--disable-component-update',
        '--disable-sync',
        '--no-first-run',
        '--use-angle=swiftshader',
        '--enable-unsafe-swiftshader',
      ],
    },
  },
  webServer: externalUrl
    ? undefined
    : {
        command: [
          `npx vite build --logLevel warn --outDir ../${dist}`,
          `npx vite build -c vite.embed.config.ts --logLevel warn --outDir ../${dist}/embed`,
          `npx vite preview --port ${port} --strictPort --outDir ../${dist}`,
        ].join(' && '),
        url: baseURL,
        reuseExistingServer: false,
        timeout: 180_000,
        stdout: 'ignore',
        stderr: 'pipe',
      },
});
