/**
 * Type of the Emscripten glue built into web/core/generated/ (Emscripten 3.1.6
 * emits no declarations). Only subdiv-core.ts imports it.
 */
declare module '*/generated/subdivlab.mjs' {
  /** Instantiates the module; `moduleArgs` become fields of the Emscripten Module object. */
  export default function createSubdivModule(moduleArgs?: Record<string, unknown>): Promise<unknown>;
}
