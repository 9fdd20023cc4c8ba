// The fuzzer of tests/node/fuzz.test.mjs, run longer: prints the counts by outcome, the
// slowest single input and every failure (with its seed, to replay).
//   node bench/fuzz.mjs [iterations=20000] [seed=1]
import * as ps from '../pkg/node/index.js';
import { fuzz } from '../tests/node/fuzz.mjs';

const iterations = Number(process.argv[2] ?? 20000);
const seed = Number(process.argv[3] ?? 1);
const t0 = performance.now();
const { counts, slowest, failures } = fuzz(ps, { seed, iterations });
const s = ((performance.now() - t0) / 1000).toFixed(1);
console.log(`iterations ${iterations} (seed ${seed}) in ${s} s: ok ${counts.ok}, clean errors ${counts.error}, traps ${counts.trap}, ` +
  `foreign throws ${counts.foreign}, broken instance ${counts.broken}, over 10 s ${counts.slow}; engine restarts ${ps.restarts()}`);
console.log(`slowest: ${Math.round(slowest.ms)} ms (${slowest.name}, case seed ${slowest.caseSeed})`);
for (const f of failures) console.log(`  ${f.outcome}: ${f.name} seed ${f.caseSeed}: ${f.message}`);
