/** A camera viewpoint that can be saved and restored (also across models). */
export interface ViewState {
  position: [number, number, number];
  target: [number, number, number];
  up: [number, number, number];
}

function isTriple(value: unknown): value is [number, number, number] {
  return Array.isArray(value) && value.length === 3 && value.every((x) => typeof x === 'number' && Number.isFinite(x));
}

/**
 * `value` as a ViewState when it is one a camera can take: three finite
 * triples, the eye off the target and a non-zero up; null otherwise.
 */
export function checkedView(value: unknown): ViewState | null {
  if (typeof value !== 'object' || value === null) return null;
  const { position, target, up } = value as Partial<ViewState>;
  if (!isTriple(position) || !isTriple(target) || !isTriple(up)) return null;
  const eye = position.map((p, i) => p - target[i]);
  if (Math.hypot(...eye) === 0 || Math.hypot(...up) === 0) return null;
  return { position: [...position], target: [...target], up: [...up] };
}

/** Parses a stored view; null when `text` is not one. */
export function parseViewState(text: string | null): ViewState | null {
  if (!text) return null;
  try {
    return checkedView(JSON.parse(text));
  } catch {
    // Not JSON: treat as no saved view.
    return null;
  }
}

/** Shortest decimal that keeps `x` to `digits` significant digits ("1.5", "-0.000123"). */
function compact(x: number, digits: number): string {
  const s = Number(x.toPrecision(digits)).toString();
  return s === '-0' ? '0' : s;
}

/**
 * The camera as a short string for links and attributes: nine numbers,
 * position, target and up, separated by commas (6 significant digits),
 * e.g. `2.1,1.7,3.8,0,0,0,0,1,0`. A view that 6 digits would make unusable
 * (an eye so close to a far-off target that both round to the same point)
 * gets the fewest more digits that keep it usable; 17 give every double back.
 */
export function formatViewString(view: ViewState): string {
  const numbers = [...view.position, ...view.target, ...view.up];
  for (let digits = 6; digits < 17; digits++) {
    const text = numbers.map((x) => compact(x, digits)).join(',');
    if (parseViewString(text) !== null) return text;
  }
  return numbers.map((x) => compact(x, 17)).join(',');
}

/** Reads {@link formatViewString}'s form; null unless it is nine finite numbers with a usable up vector. */
export function parseViewString(text: string | null | undefined): ViewState | null {
  if (!text) return null;
  const parts = text.split(',');
  if (parts.length !== 9 || parts.some((p) => p.trim() === '')) return null;
  const n = parts.map(Number);
  return checkedView({ position: [n[0], n[1], n[2]], target: [n[3], n[4], n[5]], up: [n[6], n[7], n[8]] });
}
