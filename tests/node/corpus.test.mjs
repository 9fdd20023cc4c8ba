// Issue 7's real-pattern corpus (tests/node/corpus.mjs): svg-patterns tiles, every
// geopattern generator at two seeds, simple-icons on lattices, every hero-patterns tile
// (shapes cut at the tile edge, frames with cut-outs, line work); each a 3x3 repeat of one
// period as the example and 10x10 periods out. Every case must be the example's
// periodic extension: at least 99% of ideal sites filled, no strays, no stacked
// duplicates, drift (95th percentile residual) under 1% of a period.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as ps from '../../pkg/node/index.js';
import { corpus, measure } from './corpus.mjs';

for (const c of corpus()) {
  // With the default options users get (variation on) and with variation off: each
  // placed part is its own place's part (issue 23: variation swapped parts).
  for (const options of [{}, { variation: false }]) {
    test(`${c.corpus} ${c.name} ${options.variation === false ? 'variation off' : 'defaults'}: the periodic extension`, () => {
      const r = measure(ps, c, options);
      assert.ok(r.recall >= 0.99, `recall ${r.recall}`);
      assert.equal(r.stray, 0, 'strays');
      assert.equal(r.stacked, 0, 'stacked');
      assert.equal(r.wrong, 0, 'parts put where another belongs');
      assert.ok(r.drift < 0.01, `drift ${r.drift}`);
    });
  }
}

test('compound shapes with holes come out whole: one stroke per icon, its holes as subpaths', () => {
  const c = corpus().find((x) => x.name === 'qwant/square');
  const strokes = ps.parseSvg(c.svg);
  // Qwant's mark: an outline with a hole and a separate tail, per copy.
  assert.equal(strokes.length % 9, 0);
  assert.ok(strokes.some((s) => s.breaks?.length > 0), 'a hole kept with its outline');
  const out = ps.synthesizeStrokes(strokes, { width: 320, height: 320, variation: false });
  assert.equal(out.svg.replace(/<defs>[\s\S]*<\/defs>/, '').match(/<(path|use) /g).length, out.strokes.length, 'one path or use per element');
  const whole = (list) => list.filter((s) => s.breaks?.length).length / list.length;
  assert.ok(Math.abs(whole(out.strokes) - whole(strokes)) < 0.05, `${whole(out.strokes)} against ${whole(strokes)}`);
});
