/** Keyboard shortcuts of the app; ignored while typing in a field or while a dialog is open. */
import type { OverlayName } from '../render/render-mode';
import { el } from './dom';

export interface ShortcutHandlers {
  subdivide: () => void;
  cycleRenderMode: () => void;
  toggleOverlay: (name: OverlayName) => void;
  fit: () => void;
  /** The next canonical view, front → top → side → iso (absent where there are none). */
  nextView?: () => void;
  stepLevel: (delta: number) => void;
  /** Absent where there is no file to open (an embedded viewer). */
  open?: () => void;
  cancel: () => void;
  copyImage: () => void;
  /** Stencil inspector on or off (absent where there is none). */
  toggleInspector?: () => void;
  /** Crease editing (absent where there is none, as in an embedded viewer). */
  creases?: {
    toggleEditing: () => void;
    /** Sets the selection's sharpness; false when nothing is being edited (the key does nothing). */
    sharpness: (sharpness: number) => boolean;
    /** Each false when there is nothing to undo or redo (the key is left to the page). */
    undo: () => boolean;
    redo: () => boolean;
  };
}

/** Shortcut list for the help text and the README. */
export const SHORTCUTS: readonly { keys: string; action: string }[] = [
  { keys: 'S', action: 'Subdivide (one more level)' },
  { keys: '[ / ]', action: 'Previous / next computed level' },
  { keys: 'R', action: 'Cycle render modes' },
  { keys: 'C', action: 'Toggle the control-mesh overlay' },
  { keys: 'B', action: 'Toggle the bounding box' },
  { keys: 'E', action: 'Toggle the control-edge curves' },
  { keys: 'K', action: 'Toggle the creases and corners (tagged models)' },
  { keys: 'F', action: 'Fit the view to the model (the control mesh and markers included)' },
  { keys: 'V', action: 'Next canonical view: front, top, side, iso' },
  { keys: 'O', action: 'Open a file' },
  { keys: '← ↑ → ↓', action: 'Rotate (the 3D view focused; with Shift: pan)' },
  { keys: '+ / −', action: 'Zoom in / out (the 3D view focused)' },
  { keys: 'M', action: 'Edit creases: click a control edge or vertex (Alt+click: an edge loop)' },
  { keys: '0 … 9 / I', action: 'Sharpness of the selected creases (I: infinitely sharp)' },
  { keys: 'Ctrl+Z / Ctrl+Shift+Z', action: 'Undo / redo a crease edit' },
  { keys: 'W', action: 'Inspect stencils: click a vertex of level 1 or higher for its parents and weights' },
  { keys: 'N P O V F', action: 'Halfedge explorer on: next, prev, opposite, around the vertex, around the face' },
  { keys: 'Esc', action: 'Cancel a running step' },
  { keys: 'Ctrl+C', action: 'Copy the view as PNG' },
];

/**
 * Menus last chosen from with the pointer. There a shortcut letter is a
 * shortcut (S subdivides after picking a scheme with the mouse), never
 * type-ahead that would change the menu; a menu reached with the keyboard
 * (Tab) keeps its type-ahead.
 */
const pointerChosen = new WeakSet<HTMLSelectElement>();

function isTyping(target: EventTarget | null): boolean {
  if (!(target instanceof HTMLElement)) return false;
  if (target instanceof HTMLSelectElement) return !pointerChosen.has(target);
  if (target.isContentEditable || target instanceof HTMLTextAreaElement) return true;
  if (target instanceof HTMLInputElement) {
    return !['checkbox', 'radio', 'range', 'button', 'submit', 'reset', 'file'].includes(target.type);
  }
  return false;
}

/**
 * Installs the shortcuts on `root` (the page, or one viewer element: then
 * they act only while it has focus); returns the function that removes them.
 */
export function installShortcuts(
  root: Document | HTMLElement,
  handlers: ShortcutHandlers,
  blocked: () => boolean,
): () => void {
  const onKeyDown = (event: KeyboardEvent) => {
    // The innermost target: inside a shadow root, event.target is only its host.
    const target = event.composedPath()[0] ?? event.target;
    if (event.defaultPrevented || isTyping(target) || blocked()) return;
    if ((event.ctrlKey || event.metaKey) && !event.altKey && event.key.toLowerCase() === 'c') {
      // Leave Ctrl+C alone when the user selected text to copy.
      if (document.getSelection()?.toString()) return;
      event.preventDefault();
      handlers.copyImage();
      return;
    }
    const creases = handlers.creases;
    if (creases && (event.ctrlKey || event.metaKey) && !event.altKey) {
      const key = event.key.toLowerCase();
      const done = key === 'z' ? (event.shiftKey ? creases.redo() : creases.undo()) : key === 'y' && creases.redo();
      if (done) event.preventDefault();
      return;
    }
    if (event.ctrlKey || event.metaKey || event.altKey) return;
    if (creases && /^[0-9i]$/i.test(event.key)) {
      if (creases.sharpness(event.key.toLowerCase() === 'i' ? 10 : Number(event.key))) event.preventDefault();
      return;
    }
    const action: Record<string, () => void> = {
      s: handlers.subdivide,
      r: handlers.cycleRenderMode,
      c: () => handlers.toggleOverlay('control'),
      b: () => handlers.toggleOverlay('bbox'),
      e: () => handlers.toggleOverlay('curves'),
      k: () => handlers.toggleOverlay('creases'),
      f: handlers.fit,
      ...(handlers.nextView ? { v: handlers.nextView } : {}),
      '[': () => handlers.stepLevel(-1),
      ']': () => handlers.stepLevel(1),
      ...(handlers.open ? { o: handlers.open } : {}),
      ...(creases ? { m: creases.toggleEditing } : {}),
      ...(handlers.toggleInspector ? { w: handlers.toggleInspector } : {}),
      Escape: handlers.cancel,
    };
    const run = action[event.key.length === 1 ? event.key.toLowerCase() : event.key];
    if (!run) return;
    event.preventDefault();
    run();
  };
  const listener = onKeyDown as EventListener;
  // Which menus the pointer chose from (see pointerChosen): marked on a press, unmarked when Tab
  // brings the focus there.
  let tabbing = false;
  const onPointerDown = (event: Event) => {
    const target = event.composedPath()[0];
    const select = target instanceof HTMLOptionElement ? target.parentElement : target;
    if (select instanceof HTMLSelectElement) pointerChosen.add(select);
  };
  const onTab = (event: Event) => {
    tabbing = (event as KeyboardEvent).key === 'Tab';
  };
  const onFocusIn = (event: Event) => {
    const target = event.composedPath()[0];
    if (tabbing && target instanceof HTMLSelectElement) pointerChosen.delete(target);
    tabbing = false;
  };
  root.addEventListener('pointerdown', onPointerDown, true);
  root.addEventListener('keydown', onTab, true);
  root.addEventListener('focusin', onFocusIn, true);
  root.addEventListener('keydown', listener);
  return () => {
    root.removeEventListener('keydown', listener);
    root.removeEventListener('pointerdown', onPointerDown, true);
    root.removeEventListener('keydown', onTab, true);
    root.removeEventListener('focusin', onFocusIn, true);
  };
}

/** The sidebar's collapsible list of the shortcuts. */
export function shortcutsHelp(): HTMLElement {
  return el(
    'details',
    { className: 'panel shortcuts', testId: 'help' },
    el('summary', { text: 'Keyboard shortcuts' }),
    el(
      'dl',
      {},
      ...SHORTCUTS.flatMap(({ keys, action }) => [el('dt', {}, el('kbd', { text: keys })), el('dd', { text: action })]),
    ),
  );
}
