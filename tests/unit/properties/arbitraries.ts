/** Arbitraries the property files share. */
import fc from 'fast-check';

/** Anything structured clone can carry: bigints, dates, maps, cycles, null prototypes ... */
export const anything = fc.anything({
  withBigInt: true,
  withBoxedValues: true,
  withDate: true,
  withMap: true,
  withSet: true,
  withNullPrototype: true,
  withObjectString: true,
  withSparseArray: true,
  withTypedArray: true,
});
