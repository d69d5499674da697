/**
 * Side-by-side panes as one picture: each pane's PNG in the grid the page
 * shows them in (two or three in a row, four as two by two), each labelled
 * at its foot with its scheme and level, so that a slide gets the whole
 * comparison.
 */

export interface Picture {
  png: Blob;
  label: string;
}

/** Columns of the grid for `count` panes, as the page lays them out. */
export function gridColumns(count: number): number {
  return count === 4 ? 2 : count;
}

/** One PNG of `pictures` (all of one size) in a grid, `gap` pixels apart, labels in `scale` × 12 px type. */
export async function pictureGrid(pictures: Picture[], scale: number, transparent: boolean): Promise<Blob> {
  const bitmaps = await Promise.all(pictures.map((p) => createImageBitmap(p.png)));
  const columns = gridColumns(pictures.length);
  const rows = Math.ceil(pictures.length / columns);
  const gap = Math.round(2 * scale);
  const w = bitmaps[0].width;
  const h = bitmaps[0].height;
  const canvas = document.createElement('canvas');
  canvas.width = columns * w + (columns - 1) * gap;
  canvas.height = rows * h + (rows - 1) * gap;
  const context = canvas.getContext('2d');
  if (!context) throw new Error('This browser cannot draw on a canvas.');
  if (!transparent) {
    context.fillStyle = '#d6dbe1';
    context.fillRect(0, 0, canvas.width, canvas.height);
  }
  const font = Math.round(12 * scale);
  context.font = `${font}px system-ui, sans-serif`;
  context.textBaseline = 'bottom';
  bitmaps.forEach((bitmap, i) => {
    const x = (i % columns) * (w + gap);
    const y = Math.floor(i / columns) * (h + gap);
    context.drawImage(bitmap, x, y);
    bitmap.close();
    const pad = Math.round(6 * scale);
    const text = pictures[i].label;
    const width = context.measureText(text).width;
    context.fillStyle = 'rgba(255, 255, 255, 0.88)';
    context.fillRect(x + pad, y + h - pad - font - 2 * pad, width + 2 * pad, font + 2 * pad);
    context.fillStyle = '#1f2933';
    context.fillText(text, x + 2 * pad, y + h - 2 * pad);
  });
  return new Promise<Blob>((resolve, reject) =>
    canvas.toBlob((b) => (b ? resolve(b) : reject(new Error('The browser could not encode the PNG.'))), 'image/png'),
  );
}
