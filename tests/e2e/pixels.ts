/**
 * Pixels of a part of the page in a colour the app draws: the influence
 * scale's dark end (basis functions, distances), Inspect's red. Counted on a
 * screenshot taken after the next frame is drawn.
 */
import type { Locator } from '@playwright/test';
import { readPng } from './helpers';

/** The number of pixels of `view` whose red, green and blue pass `test`. */
export async function pixelsWhere(view: Locator, test: (r: number, g: number, b: number) => boolean): Promise<number> {
  await view.page().evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  const png = readPng(await view.screenshot());
  let count = 0;
  for (let y = 0; y < png.height; ++y)
    for (let x = 0; x < png.width; ++x) {
      const [r, g, b] = png.pixel(x, y);
      if (test(r, g, b)) count++;
    }
  return count;
}

/** The influence scale's dark end (viridis purple: red and blue well above green). */
export const isViridisPurple = (r: number, g: number, b: number) => r > g + 25 && b > g + 25;

/** Inspect's red (crossing faces): red high, green and blue low. */
export const isInspectRed = (r: number, g: number, b: number) => r > 100 && g < 60 && b < 80;
