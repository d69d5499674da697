/**
 * Brings a `<subdiv-viewer>`'s SubdivViewer to what its attributes ask:
 * model (`src`, or what load() was given), rules, triangulation, scheme,
 * then levels. One pass at a time; a change during a pass runs another
 * after it, and a change that makes a download or a step useless stops it.
 * A `src` or `rules` that failed stays a standing failure (its message
 * stays, nothing is computed on the old model or rules) until it changes.
 */
import { CancelledError } from '../core/worker-client';
import { fetchMesh, type MeshText } from '../viewer/mesh-source';
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
  /** A model is shown (from `src` or load()). */
  loaded(): void;
  /** A download started or ended (progress). */
  downloadChanged(): void;
  /** A pass ended with no failure, standing or new, and no attribute problem: the message may go. */
  allWell(): void;
  /** No pass runs any more: the viewer shows what the attributes ask (or what it could reach). */
  settled(): void;
}

/** A model given to load(), waiting for the next pass. */
interface GivenModel {
  read: () => Promise<MeshText>;
  /** Named in a failure. */
  name: string;
  /** Resolves load(): shown, or superseded (by another load(), removal, cancel). */
  done: () => void;
  failed: (error: unknown) => void;
}

export class EmbedSync {
  /** The src whose model is shown, or whose load failed (see failedSrc). */
  private loadedSrc: string | null = null;
  private loadedRules = '';
  private failedSrc: string | null = null;
  private failedRules: string | null = null;
  /** Bumped when load() replaces the model: a src download that finishes later is dropped. */
  private modelEpoch = 0;
  private given: GivenModel | null = null;
  private download: { controller: AbortController; name: string } | null = null;
  private syncing: Promise<void> | null = null;
  private again = false;
  /** What the running pass aims at (null between passes). */
  private target: EmbedState | null = null;
  /** cancel(): no further level is computed until the page asks again. */
  private cancelled = false;
  private failures = 0;
  /** Attribute problems already reported: each is reported once, until its attribute changes. */
  private reported = new Set<string>();

  constructor(private readonly host: SyncHost) {}

  /** An attribute changed: a pass runs (after the running one), and a cancel no longer holds. */
  request(): Promise<void> {
    this.cancelled = false;
    return this.run();
  }

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
      this.host.settled();
    })();
    return this.syncing;
  }

  /** The pass running now, or a new one. */
  current(): Promise<void> {
    return this.syncing ?? this.request();
  }

  /** A pass runs (the viewer is being brought to the attributes). */
  get running(): boolean {
    return this.syncing !== null;
  }

  /** The level the running pass aims at (null between passes). */
  get runningLevels(): number | null {
    return this.target?.levels ?? null;
  }

  /** The file being downloaded (null when none is). */
  get downloading(): string | null {
    return this.download?.name ?? null;
  }

  /** The page asked for another src or rules: a download of the old one stops. */
  sourceChanged(): void {
    this.download?.controller.abort();
  }

  /** cancel(): the download stops, and no further level is computed until the page asks again. */
  cancel(): void {
    this.cancelled = true;
    this.download?.controller.abort();
  }

  /**
   * load(): shows `model` in place of `src`'s (a src download is stopped or
   * dropped); the last call wins. Resolves once shown or superseded; rejects
   * with the failure.
   */
  load(read: () => Promise<MeshText>, name: string, src: string): Promise<void> {
    this.given?.done();
    this.modelEpoch++;
    this.download?.controller.abort();
    this.loadedSrc = src;
    this.failedSrc = null;
    const shown = new Promise<void>((done, failed) => {
      this.given = { read, name, done, failed };
    });
    void this.request();
    return shown;
  }

  /** The next pass loads `src` again. */
  forgetSrc(): void {
    this.loadedSrc = null;
    this.failedSrc = null;
  }

  /** The element left the page. */
  reset(): void {
    this.download?.controller.abort();
    this.given?.done();
    this.given = null;
    this.loadedSrc = null;
    this.loadedRules = '';
    this.failedSrc = null;
    this.failedRules = null;
    this.reported.clear();
  }

  /** Counts a failure of the running pass. */
  noteFailure(): void {
    this.failures++;
  }

  /**
   * Reports each attribute problem once (until its attribute changes);
   * true when a problem reported before is gone (a pass may clear the message).
   */
  reportProblems(problems: EmbedState['problems']): boolean {
    const now = new Set(problems.map((p) => `${p.attribute}\n${p.message}`));
    for (const problem of problems) {
      const key = `${problem.attribute}\n${problem.message}`;
      if (!this.reported.has(key)) this.host.fail(problem.attribute, new AttributeError(problem.message));
    }
    const solved = [...this.reported].some((key) => !now.has(key));
    this.reported = now;
    return solved;
  }

  private async pass(): Promise<void> {
    const viewer = this.host.viewer();
    if (!viewer) return;
    const want = this.host.readState();
    this.target = want;
    this.failures = 0;
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
    const given = this.given;
    if (given) {
      this.given = null;
      try {
        const mesh = await given.read();
        if (!alive()) return this.superseded(given);
        await viewer.loadText(mesh.text, mesh.format, mesh.name);
        if (!alive()) return this.superseded(given);
        this.host.loaded();
        given.done();
      } catch (error) {
        if (error instanceof CancelledError) return this.superseded(given);
        if (alive()) this.host.fail(given.name, error);
        given.failed(error);
        return false;
      }
    } else if (want.src && want.src !== this.loadedSrc) {
      if (!(await this.loadSrc(viewer, want.src))) return false;
    }
    if (want.src && want.src === this.failedSrc) return this.standingFailure();
    if (want.rules !== this.loadedRules) {
      this.loadedRules = want.rules;
      this.failedRules = null;
      if (!want.rules) viewer.setSchemeOptions({});
      else if (!(await this.loadRules(viewer, want.rules))) return false;
    }
    if (want.rules && want.rules === this.failedRules) return this.standingFailure();
    // scheme="custom" without rules is an attribute problem, reported once.
    if (want.scheme === 'custom' && !want.rules) return false;
    if (viewer.state.triangulate !== want.triangulate) viewer.setTriangulate(want.triangulate);
    viewer.setScheme(want.scheme);
    return viewer.state.levelCount > 0;
  }

  private superseded(given: GivenModel): false {
    given.done();
    return false;
  }

  /** A src or rules that failed before: its message stays, nothing is computed. */
  private standingFailure(): false {
    this.failures++;
    return false;
  }

  /** Downloads and shows `src`; false when it failed or was superseded. */
  private async loadSrc(viewer: SubdivViewer, src: string): Promise<boolean> {
    this.loadedSrc = src;
    this.failedSrc = null;
    const epoch = this.modelEpoch;
    const alive = () => this.host.viewer() === viewer;
    try {
      const mesh = await this.fetching(src, (signal) => fetchMesh(src, document.baseURI, undefined, signal));
      // Superseded while downloading: by load(), a new src, or the element's removal.
      if (!alive() || epoch !== this.modelEpoch || this.host.readState().src !== src) return false;
      await viewer.loadText(mesh.text, mesh.format, mesh.name);
      if (!alive()) return false;
      this.host.loaded();
      return true;
    } catch (error) {
      if (error instanceof CancelledError) {
        // Stopped (cancel, a new src): still to be loaded, unless load() replaced it.
        if (epoch === this.modelEpoch) this.loadedSrc = null;
        return false;
      }
      if (alive() && epoch === this.modelEpoch) {
        this.failedSrc = src;
        this.host.fail(src, error);
      }
      return false;
    }
  }

  /** Downloads `rules` and hands them to the viewer; false when it failed. */
  private async loadRules(viewer: SubdivViewer, rules: string): Promise<boolean> {
    try {
      const set = await this.fetching(rules, (signal) => fetchRuleSet(rules, document.baseURI, signal));
      if (this.host.viewer() !== viewer || this.host.readState().rules !== rules) return false;
      viewer.setSchemeOptions({ rules: set });
      return true;
    } catch (error) {
      if (error instanceof CancelledError) {
        this.loadedRules = '';
        return false;
      }
      this.failedRules = rules;
      if (this.host.viewer() === viewer) this.host.fail(rules, error);
      return false;
    }
  }

  /** Runs a download that a new src or rules, cancel() or removal can stop, shown as progress. */
  private async fetching<T>(url: string, get: (signal: AbortSignal) => Promise<T>): Promise<T> {
    const controller = new AbortController();
    this.download = { controller, name: url.split(/[/?#]/).filter(Boolean).pop() ?? url };
    this.host.downloadChanged();
    try {
      return await get(controller.signal);
    } finally {
      if (this.download?.controller === controller) this.download = null;
      this.host.downloadChanged();
    }
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
