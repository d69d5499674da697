/**
 * A value as a message quotes it ("got ...", "not ..."): JSON where JSON can
 * write it, cut to {@link QUOTED_LENGTH} characters; otherwise its kind.
 * Input from a file, a page's postMessage or code can be anything, and
 * JSON.stringify throws on a bigint or a cycle: a refusal must not.
 */

/** Most characters (code points) of a quoted value before "…". */
export const QUOTED_LENGTH = 80;

export function quotedValue(value: unknown): string {
  if (typeof value === 'bigint') return `${value}n`;
  let text: string | undefined;
  try {
    text = JSON.stringify(value);
  } catch {
    // A cycle, or a toJSON that throws.
    text = undefined;
  }
  if (text === undefined) {
    if (value === undefined) return 'undefined';
    return Array.isArray(value) ? 'an array' : typeof value === 'object' ? 'an object' : `a ${typeof value}`;
  }
  const chars = [...text.slice(0, 2 * QUOTED_LENGTH + 2)];
  return chars.length > QUOTED_LENGTH ? `${chars.slice(0, QUOTED_LENGTH).join('')}…` : text;
}
