/** Rule sets from a URL (the element's `rules` attribute), read as the rules panel reads a file. */
import { parseRuleSetText, type RuleSet } from '../core/rule-set';
import { CancelledError } from '../core/worker-client';
import { httpUrl, LoadError, readLimited } from './mesh-source';

/** Largest rule file read from a URL (the shipped ones are about 1 kB). */
export const MAX_RULES_BYTES = 256 * 1024;

/**
 * Fetches and parses the rule-set JSON at `url` (http or https, relative to
 * `base`, at most {@link MAX_RULES_BYTES}); refuses with a LoadError or the
 * rule set's parse error. Aborting `signal` rejects with CancelledError.
 */
export async function fetchRuleSet(url: string, base: string, signal?: AbortSignal): Promise<RuleSet> {
  try {
    return await download(url, base, signal);
  } catch (error) {
    if (signal?.aborted) throw new CancelledError();
    throw error;
  }
}

async function download(url: string, base: string, signal?: AbortSignal): Promise<RuleSet> {
  const resolved = httpUrl(url, base);
  let response: Response;
  try {
    response = await fetch(resolved, { credentials: 'omit', signal });
  } catch {
    throw new LoadError(url, 'The rule file could not be downloaded.');
  }
  if (!response.ok) throw new LoadError(url, `The server answered ${response.status} for the rule file.`);
  const text = new TextDecoder().decode(await readLimited(response, MAX_RULES_BYTES, url));
  // Not quoted back: an embedding page may be on another origin.
  if (!text.trimStart().startsWith('{')) throw new LoadError(url, 'This is not a rule file (a JSON object).');
  return parseRuleSetText(text);
}
