// Multi-part motifs from real npm content (tests/node/motif-corpus.mjs): lucide-static
// icons of several separate paths on square, hexagonal, brick, oblique and rotated
// lattices and two icons alternating, @twemoji/svg multi-colour emoji, Hershey
// single-stroke letters (hersheytext) with a hand-made wobble per copy, and icons and
// emoji placed by hand; each a 3x3 repeat as the example and 10x10 periods out. With the
// default options users get (variation on) and with variation off, every case must be the
// example's periodic extension with each part in its own place: at least 99% of ideal
// sites filled, no strays, no stacked duplicates, no output stroke that is another part's
// drawing or paint (under 1% for the hand-made cases, whose copies each differ).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as ps from '../../pkg/node/index.js';
import { cases, measure } from './motif-corpus.mjs';

const all = cases();

test('the motif corpus: 40-80 cases, each a 3x3 repeat with its lattice vectors', () => {
  assert.ok(all.length >= 40 && all.length <= 80, `${all.length} cases`);
  for (const c of all) {
    assert.ok(c.a.length === 2 && c.b.length === 2, c.name);
    const n = ps.parseSvg(c.svg).length;
    assert.ok(n % 9 === 0 && n / 9 >= 2, `${c.name}: ${n} strokes, not a multi-part 3x3 repeat`);
  }
});

for (const c of all) {
  for (const options of [{}, { variation: false }]) {
    test(`${c.corpus} ${c.name} ${options.variation === false ? 'variation off' : 'defaults'}: the periodic extension, each part in its place`, () => {
      const r = measure(ps, c, options);
      // Every threshold missed, with the figures, in one message.
      const missed = [
        r.recall >= 0.99 || `recall ${r.recall.toFixed(4)} (${r.sites} sites)`,
        r.stray === 0 || `${r.stray} strays of ${r.out}`,
        r.stacked === 0 || `${r.stacked} stacked`,
        (c.handmade ? r.wrong < 0.01 : r.wrong === 0) || `${r.wrongCount} wrong of ${r.out} (${(r.wrong * 100).toFixed(2)}%; ${r.dressed} dressed as another part)`,
      ].filter((m) => m !== true);
      assert.deepEqual(missed, [], `drift p95 ${r.drift.toFixed(4)}, frame offset ${r.offset.toFixed(3)}`);
    });
  }
}
