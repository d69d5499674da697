/** Names of exported files: model, scheme and level, e.g. `cube-catmull-clark-L2.png`. */

/** The model's name without extension, reduced to characters safe in any file system. */
export function modelStem(modelName: string | null): string {
  const stem = (modelName ?? 'mesh').replace(/\.[^.]*$/, '');
  const safe = stem.replace(/[^A-Za-z0-9._-]+/g, '-').replace(/^-+|-+$/g, '');
  return safe || 'mesh';
}

/**
 * The comment an exported mesh file carries (OFF/OBJ `# ...`, PLY
 * `comment ...`, STL's header): where it came from, e.g.
 * `SubdivLab: bunny.off, Loop, level 2`.
 */
export function exportComment(modelName: string | null, schemeLabel: string, level: number): string {
  return `SubdivLab: ${modelName ?? 'mesh'}, ${schemeLabel}, level ${level}`;
}

export function exportFileName(modelName: string | null, scheme: string, level: number, extension: string): string {
  return `${modelStem(modelName)}-${scheme}-L${level}.${extension}`;
}
