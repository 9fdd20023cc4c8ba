// Multi-part motifs from real npm content (tests/node/motif-corpus.mjs: lucide-static
// icons on five lattices and alternating, @twemoji/svg emoji, hand-wobbled Hershey letters
// from hersheytext, icons and emoji placed by hand) in wasm under Node, with the default
// options users get and with `variation: false` side by side: example strokes, parts per
// copy, output strokes, recall of the ideal sites, strays, stacked duplicates, `wrong`
// (share of output strokes not the part of their site; the count in brackets), drift p95,
// offset (the whole output's translation from the centred frame, over the period) and
// time; then how many cases each option set gets fully right by the test's thresholds.
//   node bench/motif-corpus.mjs
import * as ps from '../pkg/node/index.js';
import { cases, measure } from '../tests/node/motif-corpus.mjs';

const SETS = [['defaults', {}], ['variation: false', { variation: false }]];
const pct = (v, d = 2) => `${(v * 100).toFixed(d)}%`;
// The test's thresholds: hand-made cases may have under 1% wrong.
const right = (c, r) => !r.error && r.recall >= 0.99 && r.stray === 0 && r.stacked === 0 && (c.handmade ? r.wrong < 0.01 : r.wrong === 0);
const both = (rs, f) => rs.map((r) => (r.error ? 'error' : f(r))).join(' \\| ');

const all = cases();
const results = all.map((c) => SETS.map(([, options]) => {
  try {
    return measure(ps, c, options);
  } catch (e) {
    return { error: e.message };
  }
}));

for (const corpus of [...new Set(all.map((c) => c.corpus))]) {
  console.log(`\n## ${corpus}  (each cell: defaults \\| variation: false)\n`);
  console.log('| case | a, b | example | parts | out | recall | strays | stacked | wrong | drift p95 | offset | ms | right |');
  console.log('|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|:---:|');
  all.forEach((c, n) => {
    if (c.corpus !== corpus) return;
    const rs = results[n];
    const first = rs.find((r) => !r.error);
    if (!first) {
      console.log(`| ${c.name} | | error: ${rs[0].error} |`);
      return;
    }
    console.log(`| ${c.name} | [${c.a}], [${c.b}] | ${first.example} | ${first.parts} | ${both(rs, (r) => r.out)} | ${both(rs, (r) => pct(r.recall))} | ${both(rs, (r) => r.stray)} | ${both(rs, (r) => r.stacked)} | ${both(rs, (r) => (r.wrongCount ? `${pct(r.wrong)} (${r.wrongCount})` : '0'))} | ${both(rs, (r) => r.drift.toFixed(4))} | ${both(rs, (r) => r.offset.toFixed(3))} | ${both(rs, (r) => r.ms.toFixed(0))} | ${rs.map((r) => (right(c, r) ? 'yes' : 'no')).join(' \\| ')} |`);
  });
}

console.log('\n## Totals: cases fully right\n');
console.log(`| corpus | cases | ${SETS.map(([l]) => l).join(' | ')} | both |`);
console.log(`|---|---:|${SETS.map(() => '---:').join('|')}|---:|`);
for (const corpus of [...new Set(all.map((c) => c.corpus)), 'all']) {
  const idx = all.map((c, n) => n).filter((n) => corpus === 'all' || all[n].corpus === corpus);
  const good = (s) => idx.filter((n) => right(all[n], results[n][s])).length;
  console.log(`| ${corpus} | ${idx.length} | ${SETS.map((_, s) => good(s)).join(' | ')} | ${idx.filter((n) => SETS.every((_, s) => right(all[n], results[n][s]))).length} |`);
}
