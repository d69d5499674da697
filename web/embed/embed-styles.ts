/** The element's shadow-DOM styles: sized by the page, light and dark, quiet when motion is unwanted. */
export const EMBED_CSS = `
:host {
  display: block;
  position: relative;
  width: 100%;
  height: 320px;
  min-height: 120px;
  color-scheme: light dark;
  font: 13px/1.35 system-ui, -apple-system, 'Segoe UI', Roboto, sans-serif;
  /* A slide deck centres its text (reveal.js): the caption's lines stay aligned with its colour bar. */
  text-align: start;
  color: #1f2933;
  background: #f3f4f6;
  border-radius: 6px;
  overflow: hidden;
  contain: content;
}
:host([hidden]), [hidden] { display: none !important; }
/* With a background of the page's choosing, the picture paints it (transparent shows the page). */
:host([background]) { background: transparent; }
:host(:focus-visible) { outline: 3px solid #2563eb; outline-offset: 2px; }
.frame { position: absolute; inset: 0; display: flex; flex-direction: column; container-type: inline-size; }
.panes {
  flex: 1 1 auto; min-height: 0; display: grid; grid-template-columns: minmax(0, 1fr);
  grid-auto-rows: minmax(0, 1fr); gap: 2px; background: #d6dbe1;
}
.panes[data-count="2"], .panes[data-count="4"] { grid-template-columns: repeat(2, minmax(0, 1fr)); }
.panes[data-count="3"] { grid-template-columns: repeat(3, minmax(0, 1fr)); }
.stage, .pane { position: relative; min-height: 0; min-width: 0; overflow: hidden; }
.pane-view { position: absolute; inset: 0; }
.pane-label {
  position: absolute; left: 6px; bottom: 6px; padding: 1px 6px; border-radius: 4px; font-size: 12px;
  background: rgba(255, 255, 255, 0.88); border: 1px solid #d6dbe1; pointer-events: none;
}
.stage:focus-visible { outline: 3px solid #2563eb; outline-offset: -3px; }
.bar {
  display: flex; flex-wrap: wrap; align-items: center; gap: 6px;
  padding: 5px 8px; background: rgba(255, 255, 255, 0.92); border-top: 1px solid #d6dbe1;
}
.bar[hidden] { display: none; }
.bar button, .bar select {
  font: inherit; color: inherit; background: #fff; border: 1px solid #b8c0ca; border-radius: 4px;
  padding: 2px 8px; min-height: 26px;
}
.bar button:disabled { opacity: 0.45; }
.bar label { display: inline-flex; align-items: center; gap: 3px; }
.level { min-width: 5.5em; text-align: center; font-variant-numeric: tabular-nums; }
.facts { margin-left: auto; font-variant-numeric: tabular-nums; color: #52606d; }
.message {
  position: absolute; left: 8px; right: 8px; top: 8px; padding: 6px 8px; border-radius: 4px;
  background: #fdecea; color: #8a1c1c; border: 1px solid #f5c2c0; white-space: pre-wrap;
}
.busy {
  position: absolute; right: 8px; top: 8px; display: flex; gap: 6px; align-items: center;
  padding: 4px 8px; border-radius: 4px; background: rgba(255, 255, 255, 0.92); border: 1px solid #d6dbe1;
}
.busy button { font: inherit; }
.status {
  position: absolute; width: 1px; height: 1px; overflow: hidden; clip-path: inset(50%); white-space: nowrap;
}
.placeholder {
  position: absolute; inset: 0; display: grid; place-items: center; color: #52606d; pointer-events: none;
}
/* The teaching tool's caption: a row of its own above the controls, so it never covers the model. */
.tool {
  flex: 0 0 auto; padding: 4px 8px; background: rgba(255, 255, 255, 0.92); border-top: 1px solid #d6dbe1;
  max-height: 40%; overflow: auto;
}
.tool p { margin: 0; }
.tool-line { font-variant-numeric: tabular-nums; overflow-wrap: anywhere; }
.tool-line.hint, .tool-note { color: #52606d; }
/* The formula on one line (the whole of it in the tooltip): the picture keeps its height in a small viewer. */
.tool-note { font-size: 12px; white-space: nowrap; overflow: hidden; text-overflow: ellipsis; }
.tool-legend { display: flex; align-items: center; gap: 6px; margin-top: 2px; font-size: 12px; color: #52606d; }
.tool-bar { flex: 0 1 14em; height: 10px; border-radius: 2px; }
.split { display: inline-flex; align-items: center; gap: 6px; }
.split input { width: 8em; margin: 0; }
/* Narrow viewers keep one row of controls: the counts and labels give way first. */
@container (max-width: 440px) {
  .facts { display: none; }
  .bar label { font-size: 0; gap: 0; }
  .bar select { max-width: 8.5em; }
}
@media (prefers-color-scheme: dark) {
  :host { color: #e4e7eb; background: #1f2328; }
  .bar, .busy, .tool, .pane-label { background: rgba(31, 35, 40, 0.92); border-color: #3e4650; }
  .panes { background: #3e4650; }
  .tool-line.hint, .tool-note, .tool-legend { color: #aab3bd; }
  .bar button, .bar select { background: #2b3036; border-color: #56606b; }
  .facts, .placeholder { color: #aab3bd; }
  .message { background: #3b1f1f; color: #ffd7d5; border-color: #7a2e2b; }
}
@media (prefers-reduced-motion: reduce) {
  * { transition: none !important; animation: none !important; }
}
`;
