// Issue 7's real-pattern corpus in wasm under Node: per case and per corpus, recall of
// the ideal sites, strays, stacked duplicates, parts put where another belongs, drift and
// time (see tests/node/corpus.mjs), with the default options users get and with
// `variation: false`.
//   node bench/corpus.mjs [--cases]
import * as ps from '../pkg/node/index.js';
import { corpus, measure } from '../tests/node/corpus.mjs';

const fmt = (v, d = 3) => (typeof v === 'number' ? v.toFixed(d) : v);
const ok = (r) => !r.error && r.recall >= 0.99 && r.stray === 0 && r.stacked === 0 && r.wrong === 0 && r.drift < 0.01;
for (const [label, options] of [['defaults', {}], ['variation: false', { variation: false }]]) {
  const rows = corpus().map((c) => {
    try {
      return measure(ps, c, options);
    } catch (e) {
      return { corpus: c.corpus, name: c.name, error: e.message };
    }
  });
  console.log(`\n## ${label}`);
  if (process.argv.includes('--cases')) {
    console.log('| corpus | case | example | out | sites | recall | strays | stacked | wrong | drift p95 | ms |\n|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|');
    for (const r of rows) {
      console.log(r.error ? `| ${r.corpus} | ${r.name} | error: ${r.error} |` : `| ${r.corpus} | ${r.name} | ${r.example} | ${r.out} | ${r.sites} | ${fmt(r.recall * 100, 2)}% | ${r.stray} | ${r.stacked} | ${r.wrong} | ${fmt(r.drift, 4)} | ${fmt(r.ms, 0)} |`);
    }
  }
  console.log('| corpus | cases | right | min recall | strays | stacked | wrong | max drift p95 | median ms | max ms |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|');
  for (const name of [...new Set(rows.map((r) => r.corpus))]) {
    const rs = rows.filter((r) => r.corpus === name);
    const good = rs.filter((r) => !r.error);
    const ms = good.map((r) => r.ms).sort((p, q) => p - q);
    const sum = (k) => good.reduce((s, r) => s + r[k], 0);
    console.log(`| ${name} | ${rs.length} | ${rs.filter(ok).length} | ${fmt(Math.min(...good.map((r) => r.recall)) * 100, 2)}% | ${sum('stray')} | ${sum('stacked')} | ${sum('wrong')} | ${fmt(Math.max(...good.map((r) => r.drift)), 4)} | ${fmt(ms[ms.length >> 1], 0)} | ${fmt(ms.at(-1), 0)} |`);
  }
}
