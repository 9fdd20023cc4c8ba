// The seeded fuzz run of the test command (bench/fuzz.mjs runs the same fuzzer longer):
// no input traps, leaves the instance broken, or throws anything but a clear Error.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as ps from '../../pkg/node/index.js';
import { fuzz } from './fuzz.mjs';

test('2,000 mutated inputs: clean errors or results, never a trap, the instance always works', () => {
  const { counts, slowest, failures } = fuzz(ps, { seed: 7, iterations: 2000 });
  console.log(JSON.stringify({ counts, slowest: { ...slowest, ms: Math.round(slowest.ms) } }));
  assert.deepEqual(failures, []);
  assert.ok(counts.ok > 100 && counts.error > 100, 'both paths exercised');
  assert.equal(ps.restarts(), 0);
});
