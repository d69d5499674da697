/** Codes of SubdivError, as the C++ core names them (Status_code in mesh_types.h). */
export type SubdivErrorCode =
  | 'parse_error'
  | 'invalid_mesh'
  /** An orientable mesh whose faces disagree: reading with `repairOrientation` turns them. */
  | 'inconsistent_orientation'
  | 'not_triangles'
  | 'too_large'
  | 'invalid_argument'
  | 'internal_error';

/** The one error the core's API throws. `line` is 1-based, 0 when it does not apply. */
export class SubdivError extends Error {
  readonly code: SubdivErrorCode;
  readonly line: number;

  constructor(code: SubdivErrorCode, message: string, line = 0) {
    super(message);
    this.name = 'SubdivError';
    this.code = code;
    this.line = line;
  }
}
