/**
 * The look of a model opened after the first visit's sample. The first visit
 * shows polygon edges and the control mesh, which suit a course model of a
 * few dozen faces; over a scan of thousands the edges are a dark mass and
 * the cage hides the surface. So while the user has not chosen a render mode
 * or the cage (and no link has), each model opened gets the look that suits
 * its size; what the user, a link or a tool set stays.
 */
import type { RenderMode } from '../render/render-mode';

/**
 * Models of up to this many faces open with their polygon edges and cage.
 * A count, not the edges' density on screen, so that a model opens the same
 * in any window. Measured in a 1024×700 window: a torus of 1,000 quads has
 * edges 21 px long on screen (drawn at 0.6 opacity, line-style.ts), each
 * quad still one to look at; CGAL's elephant (5,558 triangles) 12 px, a web
 * of scan triangles over the shape, under a cage of 8,337 edges once stepped.
 */
export const FIRST_LOOK_MAX_FACES = 1000;

/** The display settings the first look sets. */
export interface Look {
  renderMode: RenderMode;
  /** The control-mesh overlay (the cage). */
  control: boolean;
}

/** The look that suits a model of `faces` faces: polygon edges and cage, or smooth shading without them. */
export function lookFor(faces: number): Look {
  return faces <= FIRST_LOOK_MAX_FACES
    ? { renderMode: 'edges', control: true }
    : { renderMode: 'smooth', control: false };
}

/** What the first look changes on the viewer. */
export interface LookTarget {
  readonly state: { readonly renderMode: RenderMode; readonly overlays: { readonly control: boolean } };
  setRenderMode(mode: RenderMode): void;
  setOverlay(name: 'control', visible: boolean): void;
}

/**
 * Which of the render mode and the cage still hold a default (the first
 * visit's, or one this class set), and the value it was: a setting the user
 * chose, or that changed since (a tool turned the cage on), is left alone.
 */
export class FirstLook {
  private mode: RenderMode | null = null;
  private cage: boolean | null = null;

  /** The first visit's display `look` is a default, not a choice. */
  begin(look: Look): void {
    this.mode = look.renderMode;
    this.cage = look.control;
  }

  /** The user chose the render mode or the cage: it stays from now on. */
  chose(setting: 'renderMode' | 'control'): void {
    if (setting === 'renderMode') this.mode = null;
    else this.cage = null;
  }

  /** A link (or Back, Forward, an edited hash) set the display: all of it stays. */
  end(): void {
    this.mode = null;
    this.cage = null;
  }

  /** Gives a newly opened model of `faces` faces the look that suits it, in the settings still at their default. */
  apply(target: LookTarget, faces: number): void {
    const look = lookFor(faces);
    const { renderMode, overlays } = target.state;
    if (this.mode !== null && this.mode === renderMode) {
      target.setRenderMode(look.renderMode);
      this.mode = look.renderMode;
    } else {
      this.mode = null;
    }
    if (this.cage !== null && this.cage === overlays.control) {
      target.setOverlay('control', look.control);
      this.cage = look.control;
    } else {
      this.cage = null;
    }
  }
}
