/**
 * The core's judgement of a custom rule set without a model (check_rules:
 * every weight finite, every stencil summing to 1, naming the rule and the
 * valence). The rules panel shows that message; there is no second validator
 * in the UI.
 */
import type { RuleSet } from '../core/rule-set';
import { CancelledError, type CoreSession } from '../core/worker-client';

/** Resolves when the core accepts `rules`; rejects with its SubdivError (code invalid_argument) otherwise. */
export async function checkRulesInCore(core: CoreSession, rules: RuleSet): Promise<void> {
  try {
    await core.checkRules(rules);
  } catch (error) {
    // Cancelling a step takes this session's queued requests with it: ask again.
    if (!(error instanceof CancelledError)) throw error;
    await core.checkRules(rules);
  }
}
