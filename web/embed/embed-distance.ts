/**
 * How far a viewer is from the viewport, for a page with many of them: it
 * starts when it comes near, and gives its GPU memory back when it is far.
 */

/** Margin around the viewport within which a viewer starts. */
export const START_MARGIN = '200px 0px';
/** Margin beyond which a viewer frees its GPU copies (1.5 screens above or below). */
export const RELEASE_MARGIN = '150% 0px';

/** Calls `onNear` once, when `element` comes within {@link START_MARGIN}; returns the function that stops watching. */
export function whenNear(element: Element, onNear: () => void): () => void {
  const observer = new IntersectionObserver(
    (entries) => {
      if (!entries.some((e) => e.isIntersecting)) return;
      observer.disconnect();
      onNear();
    },
    { rootMargin: START_MARGIN },
  );
  observer.observe(element);
  return () => observer.disconnect();
}

/**
 * Calls `onFar` when `element` goes beyond {@link RELEASE_MARGIN} and
 * `onBack` when it comes within it again; returns the function that stops watching.
 */
export function whenFar(element: Element, onFar: () => void, onBack: () => void): () => void {
  let far = false;
  const observer = new IntersectionObserver(
    (entries) => {
      const near = entries.some((e) => e.isIntersecting);
      if (near === !far) return;
      far = !near;
      if (far) onFar();
      else onBack();
    },
    { rootMargin: RELEASE_MARGIN },
  );
  observer.observe(element);
  return () => observer.disconnect();
}
