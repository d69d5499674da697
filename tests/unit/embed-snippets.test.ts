/** The share link and the embed snippets (web/app/embed-snippets.ts): exact text, escaping, absolute URLs. */
import { describe, expect, it } from 'vitest';
import { elementSnippet, escapeAttribute, iframeSnippet, shareLink } from '../../web/app/embed-snippets';
import { parseViewerParams } from '../../web/viewer/viewer-params';

const subject = { appBase: 'https://example.org/lab/', modelName: 'cube.off', faces: 24 };

describe('embed snippets', () => {
  it('escape what would end or open an attribute', () => {
    expect(escapeAttribute('a"b&c<d>')).toBe('a&quot;b&amp;c&lt;d&gt;');
  });

  it('write the element with absolute src, scheme and levels always, overlays only when on', () => {
    const code = elementSnippet(
      { src: 'meshes/cube.off', scheme: 'catmull-clark', levels: 1, renderMode: 'smooth' },
      subject,
    );
    expect(code).toBe(
      '<script defer src="https://example.org/lab/embed/subdiv-viewer.js"></script>\n' +
        '<subdiv-viewer\n  src="https://example.org/lab/meshes/cube.off"\n  scheme="catmull-clark"\n  levels="1"\n' +
        '  render-mode="smooth"\n  controls="minimal"\n' +
        '  alt="cube.off after 1 Catmull-Clark subdivision step (24 faces), smooth shaded."\n></subdiv-viewer>',
    );
  });

  it('write an iframe query the viewer-params parser reads back, with a src holding & and a quote escaped', () => {
    const src = 'https://data.example.org/m.off?a=1&b="x"';
    const code = iframeSnippet({ src, scheme: 'loop', levels: 2, overlays: { bbox: true } }, subject);
    const attr = /src="([^"]*)"/.exec(code)?.[1] ?? '';
    const url = new URL(attr.replace(/&quot;/g, '"').replace(/&amp;/g, '&'));
    expect(`${url.origin}${url.pathname}`).toBe('https://example.org/lab/embed.html');
    const { params, problems } = parseViewerParams(url.search);
    expect(problems).toEqual([]);
    expect(params).toEqual({
      src: new URL(src).href,
      scheme: 'loop',
      levels: 2,
      overlays: { bbox: true },
      controls: 'minimal',
    });
  });

  it('make the share link from the page address without its query', () => {
    const link = shareLink('https://example.org/lab/index.html?src=old.off#x', { src: 'meshes/cube.off', levels: 0 });
    expect(link).toBe('https://example.org/lab/index.html#src=meshes/cube.off&levels=0');
  });
});
