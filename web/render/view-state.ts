/** A camera viewpoint that can be saved and restored (also across models). */
export interface ViewState {
  position: [number, number, number];
  target: [number, number, number];
  up: [number, number, number];
}

function isTriple(value: unknown): value is [number, number, number] {
  return Array.isArray(value) && value.length === 3 && value.every((x) => typeof x === 'number' && Number.isFinite(x));
}

/** Parses a stored view; null when `text` is not one. */
export function parseViewState(text: string | null): ViewState | null {
  if (!text) return null;
  try {
    const value = JSON.parse(text) as Partial<ViewState>;
    if (isTriple(value.position) && isTriple(value.target) && isTriple(value.up)) {
      return { position: value.position, target: value.target, up: value.up };
    }
  } catch {
    // Not JSON: treat as no saved view.
  }
  return null;
}
