/** Errors as the user reads them, in the app and in an embedded viewer. */
import { SubdivError } from '../core/subdiv-error';

/** The user-facing sentence of an error; the core's line number is added when the message lacks it. */
export function messageOf(error: unknown): string {
  if (error instanceof SubdivError) {
    const hasLine = error.line > 0 && !/\bline\s+\d/i.test(error.message);
    return hasLine ? `line ${error.line}: ${error.message}` : error.message;
  }
  if (error instanceof Error) return error.message;
  return String(error);
}
