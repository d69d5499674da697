/** Rule sets from a URL (the element's `rules` attribute), read as the rules panel reads a file. */
import { parseRuleSetText, type RuleSet } from '../core/rule-set';
import { LoadError } from './mesh-source';

/** Fetches and parses the rule-set JSON at `url` (relative to `base`); refuses with a LoadError or parse error. */
export async function fetchRuleSet(url: string, base: string): Promise<RuleSet> {
  let response: Response;
  try {
    response = await fetch(new URL(url, base), { credentials: 'omit' });
  } catch {
    throw new LoadError(url, 'The rule file could not be downloaded.');
  }
  if (!response.ok) throw new LoadError(url, `The server answered ${response.status} for the rule file.`);
  return parseRuleSetText(await response.text());
}
