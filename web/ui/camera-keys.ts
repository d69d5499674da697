/** Camera keys while the 3D view has focus: arrows rotate, Shift+arrows pan, +/− zoom. */
import type { SceneView } from '../render/scene-view';

/** Moves the camera of `view` for `event`'s key (and prevents its default) when it is a camera key. */
export function cameraKey(event: KeyboardEvent, view: SceneView): void {
  if (event.ctrlKey || event.metaKey || event.altKey) return;
  const step = 10;
  const moves: Record<string, () => void> = event.shiftKey
    ? {
        ArrowLeft: () => view.pan(0.05, 0),
        ArrowRight: () => view.pan(-0.05, 0),
        ArrowUp: () => view.pan(0, -0.05),
        ArrowDown: () => view.pan(0, 0.05),
      }
    : {
        ArrowLeft: () => view.orbit(-step, 0),
        ArrowRight: () => view.orbit(step, 0),
        ArrowUp: () => view.orbit(0, -step),
        ArrowDown: () => view.orbit(0, step),
      };
  const zooms: Record<string, number> = { '+': 1 / 1.2, '=': 1 / 1.2, '-': 1.2, _: 1.2 };
  const move = moves[event.key] ?? (event.key in zooms ? () => view.zoom(zooms[event.key]) : undefined);
  if (!move) return;
  event.preventDefault();
  move();
}
