// Autocomplete through the package under Node: a row drawn three times gets its next
// copies at the row's period; a fourth stroke off the row dismisses them; a freehand
// scribble gets nothing; bad options get a message.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as ps from '../../pkg/node/index.js';

const leaf = (x, y) => ({ points: [[x, y], [x + 4, y - 8], [x + 8, y]], width: 2, stroke: '#2a6a2a' });
const row = (n) => Array.from({ length: n }, (_, i) => leaf(20 + 30 * i, 50));

test('a motif drawn three times gets its next copies along the row', () => {
  assert.equal(ps.suggestStrokes(row(2), { region: [0, 0, 400, 100] }).strokes.length, 0);
  const s = ps.suggestStrokes(row(3), { region: [0, 0, 400, 100] });
  assert.deepEqual(s.periods, [[30, 0]]);
  assert.deepEqual(s.strokes.map((t) => t.points[0][0]), [110, 140, 170]);
  assert.equal(s.confidence.length, 3);
  assert.ok(s.confidence.every((c) => c > 0 && c <= 1));
  // fill: every copy that fits the canvas.
  const all = ps.suggestStrokes(row(3), { region: [0, 0, 400, 100], fill: true });
  assert.equal(all.strokes.length, 10); // x = 110 ... 380
  const off = [...row(3), leaf(60, 90)];
  assert.equal(ps.suggestStrokes(off, { region: [0, 0, 400, 100] }).strokes.length, 0);
});

test('a scribble gets no proposals and bad options a message', () => {
  const scribble = [
    { points: [[10, 10], [30, 40], [35, 12]], width: 2 },
    { points: [[80, 20], [60, 70]], width: 4 },
    { points: [[100, 100], [120, 90], [140, 130], [150, 100]], width: 1 },
    { points: [[40, 80], [42, 82]], width: 3 },
  ];
  const s = ps.suggestStrokes(scribble, {});
  assert.equal(s.strokes.length, 0);
  assert.match(s.reason, /no repetition/);
  assert.throws(() => ps.suggestStrokes(row(3), { fill: true }), /fill needs a region/);
  assert.throws(() => ps.suggestStrokes(row(3), { count: 1000 }), /at most 64/);
  assert.throws(() => ps.suggestStrokes(row(3), { regoin: [0, 0, 1, 1] }), /unknown option `regoin`/);
  assert.throws(() => ps.suggestStrokes(row(3), { suggested: [3] }), /suggested lists stroke 3, but there are 3 strokes/);
});
