// Strokes' points cross into wasm as one Float64Array (js/pkg/flat.js): the results
// must be exactly those of the points read pair by pair, and every stroke the flat
// copy cannot stand for (class instances, getters, bad points) must still be read,
// and named when wrong, as before.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as ps from '../../pkg/node/index.js';
import { flatStrokes } from '../../pkg/flat.js';

const row = Array.from({ length: 8 }, (_, i) => ({
  points: [[10 + i * 20, 10], [14 + i * 20, 16 + (i % 3)], [18 + i * 20, 10]],
  width: 1 + (i % 2),
  stroke: i % 2 ? '#ff0000' : '#000000',
}));

test('flattened points: one buffer, the same numbers, the other fields kept', () => {
  const flat = flatStrokes(row);
  assert.notEqual(flat, row);
  assert.ok(flat.every((s) => s.points instanceof Float64Array));
  assert.equal(flat[0].points.buffer, flat[7].points.buffer, 'one buffer for all');
  assert.deepEqual(Array.from(flat[3].points), row[3].points.flat());
  assert.deepEqual({ ...flat[5], points: null }, { ...row[5], points: null });
  assert.ok(Array.isArray(row[0].points), 'the caller\'s strokes are untouched');
});

test('the engine reads Float64Array points as it reads pairs', () => {
  const opts = { width: 300, height: 120, seed: 4 };
  const pairs = ps.synthesizeStrokes(row, opts);
  const typed = ps.synthesizeStrokes(row.map((s) => ({ ...s, points: Float64Array.from(s.points.flat()) })), opts);
  assert.ok(pairs.strokes.length >= 14, `${pairs.strokes.length} strokes`);
  assert.deepEqual(typed.strokes, pairs.strokes);
  assert.deepEqual(typed.classes, pairs.classes);
  assert.throws(() => ps.classifyStrokes([{ points: new Float64Array(5), width: 1 }, ...row]), /Stroke 0's points, a Float64Array, must hold x, y pairs: an even count of numbers, got 5/);
});

test('strokes the flat copy does not stand for are read as before', () => {
  class Dash {
    constructor(x) { this.x = x; }
    get points() { return [[this.x, 0], [this.x + 4, 4]]; }
    get width() { return 2; }
  }
  const dashes = Array.from({ length: 6 }, (_, i) => new Dash(i * 10));
  const flat = flatStrokes(dashes);
  assert.ok(flat.every((s, i) => s === dashes[i]), 'class instances are passed as they are');
  const c = ps.classifyStrokes(dashes);
  assert.equal(c.count, 1);
  // A points getter that answers longer the second time: left to the engine whole.
  let reads = 0;
  const shifty = [{ get points() { reads += 1; return reads > 1 ? [[0, 0], [1, 1], [2, 0]] : [[0, 0], [1, 1]]; }, width: 1 }];
  assert.equal(flatStrokes(shifty), shifty);
  // Bad points keep their exact message.
  assert.throws(() => ps.classifyStrokes([{ points: [[0, 0], ['a', 1]], width: 1 }]), /Stroke 0's point 1 must be \[x, y\] with two numbers, got an array/);
});
