/**
 * Brings a `<subdiv-viewer>`'s SubdivViewer to what its attributes ask:
 * model (`src`, or a text given to load()), rules, triangulation, scheme,
 * then levels. One pass at a time; a change during a pass runs another, and
 * stops a step or a download that the change makes useless.
 */
import { CancelledError } from '../core/worker-client';
import { fetchMesh } from '../viewer/mesh-source';
import { fetchRuleSet } from '../viewer/rules-source';
import type { SubdivViewer } from '../viewer/subdiv-viewer';
import { AttributeError } from './embed-events';
import type { EmbedState } from './embed-state';

/** What the sync needs from its element. */
export interface SyncHost {
  /** The viewer, or null once the element was removed from the page. */
  viewer(): SubdivViewer | null;
  /** The attributes as they read now. */
  readState(): EmbedState;
  /** Reports a failure (message and `error` event); CancelledError is not one. */
  fail(source: string, error: unknown): void;
  /** A model from `src` is shown. */
  loaded(): void;
  /** A download started or ended (progress). */
  downloadChanged(): void;
  /** A pass ended without any failure and with no attribute problem left: the message may go. */
  allWell(): void;
}

export class EmbedSync {
  /** The src whose model is shown (or whose load failed: not retried until the attribute changes). */
  private loadedSrc: string | null = null;
  private loadedRules = '';
  /** Bumped when load() replaces the model: a src download that finishes later is dropped. */
  private modelEpoch = 0;
  private download: { controller: AbortController; name: string } | null = null;
  private syncing: Promise<void> | null = null;
  private again = false;
  /** What the running pass aims at (null between passes). */
  private target: EmbedState | null = null;
  private cancelled = false;
  private failures = 0;
  /** Attribute problems already reported: each is reported once, until its attribute changes. */
  private reported = new Set<string>();

  constructor(private readonly host: SyncHost) {}

  /** Runs a pass (or, during one, asks for another after it); resolves when no pass runs. */
  run(): Promise<void> {
    if (!this.host.viewer()) return Promise.resolve();
    if (this.syncing) {
      this.again = true;
      return this.syncing;
    }
    this.syncing = (async () => {
      try {
        do {
          this.again = false;
          await this.pass();
        } while (this.again && this.host.viewer());
      } finally {
        this.syncing = null;
      }
    })();
    return this.syncing;
  }

  /** The pass running now, or a new one. */
  current(): Promise<void> {
    return this.syncing ?? this.run();
  }

  /** The level the running pass aims at (null between passes). */
  get runningLevels(): number | null {
    return this.target?.levels ?? null;
  }

  /** The file name of the src being downloaded (null when none is). */
  get downloading(): string | null {
    return this.download?.name ?? null;
  }

  /** The page asked for another src: the download of the old one stops. */
  srcChanged(): void {
    this.download?.controller.abort();
  }

  /** cancel(): the download stops and the running pass computes no further level. */
  cancel(): void {
    if (this.target) this.cancelled = true;
    this.download?.controller.abort();
  }

  /** load() shows a model of its own: a src download is stopped (or dropped), and `src` counts as done. */
  replaceModel(src: string): void {
    this.modelEpoch++;
    this.download?.controller.abort();
    this.loadedSrc = src;
  }

  /** The next pass loads `src` again. */
  forgetSrc(): void {
    this.loadedSrc = null;
  }

  /** The element left the page. */
  reset(): void {
    this.download?.controller.abort();
    this.loadedSrc = null;
    this.loadedRules = '';
    this.reported.clear();
  }

  /** Counts a failure of the running pass. */
  noteFailure(): void {
    this.failures++;
  }

  /** Reports each attribute problem once (until the attribute changes). */
  reportProblems(problems: EmbedState['problems']): void {
    const now = new Set(problems.map((p) => `${p.attribute}\n${p.message}`));
    for (const problem of problems) {
      const key = `${problem.attribute}\n${problem.message}`;
      if (!this.reported.has(key)) this.host.fail(problem.attribute, new AttributeError(problem.message));
    }
    this.reported = now;
  }

  private async pass(): Promise<void> {
    const viewer = this.host.viewer();
    if (!viewer) return;
    const want = this.host.readState();
    this.target = want;
    this.failures = 0;
    this.cancelled = false;
    try {
      if (await this.model(viewer, want)) await this.levels(viewer, want);
    } finally {
      this.target = null;
    }
    const problems = this.host.readState().problems.length;
    if (this.host.viewer() === viewer && this.failures === 0 && problems === 0 && !this.again) this.host.allWell();
  }

  /** Model, rules, triangulation and scheme; false when the pass cannot go on (failed, superseded, removed). */
  private async model(viewer: SubdivViewer, want: EmbedState): Promise<boolean> {
    this.reportProblems(want.problems);
    const alive = () => this.host.viewer() === viewer;
    if (want.src && want.src !== this.loadedSrc) {
      this.loadedSrc = want.src;
      const epoch = this.modelEpoch;
      const controller = new AbortController();
      this.download = { controller, name: want.src.split(/[/?#]/).filter(Boolean).pop() ?? want.src };
      this.host.downloadChanged();
      try {
        const mesh = await fetchMesh(want.src, document.baseURI, undefined, controller.signal).finally(() => {
          if (this.download?.controller === controller) this.download = null;
          if (alive()) this.host.downloadChanged();
        });
        // Superseded while downloading: by load(), a new src, or the element's removal.
        if (!alive() || epoch !== this.modelEpoch || this.host.readState().src !== want.src) return false;
        await viewer.loadText(mesh.text, mesh.format, mesh.name);
        if (!alive()) return false;
        this.host.loaded();
      } catch (error) {
        // Cancelled (Esc while loading): the src is still to be loaded, unless load() replaced it.
        if (error instanceof CancelledError && epoch === this.modelEpoch) this.loadedSrc = null;
        if (alive()) this.host.fail(want.src, error);
        return false;
      }
    }
    if (want.rules !== this.loadedRules) {
      this.loadedRules = want.rules;
      try {
        viewer.setSchemeOptions(want.rules ? { rules: await fetchRuleSet(want.rules, document.baseURI) } : {});
      } catch (error) {
        if (alive()) this.host.fail(want.rules, error);
        return false;
      }
      if (!alive()) return false;
    }
    // scheme="custom" without rules is an attribute problem, reported once.
    if (want.scheme === 'custom' && !want.rules) return false;
    if (viewer.state.triangulate !== want.triangulate) viewer.setTriangulate(want.triangulate);
    viewer.setScheme(want.scheme);
    return viewer.state.levelCount > 0;
  }

  /** Computes the levels up to the one asked and shows it (or the highest reached). */
  private async levels(viewer: SubdivViewer, want: EmbedState): Promise<void> {
    try {
      while (viewer.state.levelCount - 1 < want.levels && !this.again && !this.cancelled) {
        const stepped = await viewer.subdivide();
        if (this.host.viewer() !== viewer) return;
        if (!stepped) break;
      }
    } catch (error) {
      if (this.host.viewer() !== viewer) return;
      this.host.fail(viewer.state.modelName ?? 'mesh', error);
    }
    viewer.setLevel(want.levels);
  }
}
