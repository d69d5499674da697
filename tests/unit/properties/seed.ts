/**
 * One seed for every property, so `npm test` runs the same cases each time
 * and a commit is not failed by a case its change did not touch.
 * SUBDIVLAB_FC_SEED=random draws a new seed each run (a failure prints it
 * with the shrunk counterexample); SUBDIVLAB_FC_SEED=N replays seed N.
 */
import fc from 'fast-check';

const given = process.env.SUBDIVLAB_FC_SEED;
if (given !== 'random') fc.configureGlobal({ seed: given === undefined ? 20261124 : Number(given) });
