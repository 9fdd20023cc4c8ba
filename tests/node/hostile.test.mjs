// Hostile input through the built package (issue 9's cases, bench/hostile.mjs): each
// gets a result or a clear Error naming what was wrong, quickly, and the instance keeps
// working. And when a trap does happen (a bug), the engine replaces its instance.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import * as ps from '../../pkg/node/index.js';
import * as glue from '../../pkg/wasm/full.js';
import { engine } from '../../pkg/instance.js';
import { CASES } from '../../bench/hostile.mjs';

// What each case must answer (a result when absent).
const WANT = {
  '<g> nested 240 deep': /nests 242 levels deep.*limit is 100/,
  '<a> nested 240 deep': /nests 242 levels deep/,
  '400 nested scale(10)': /nests 402 levels deep/,
  'chain of 200 <use>': /nests 203 levels deep/,
  'strokeTile, width 1e300': /more than 100000 strokes.*thinner/,
  'strokeTile, width 20000': /more than 100000 strokes/,
  'strokeTile, width 60000': /more than 100000 strokes/,
  'decodeImage({ length: -1 })': /decodeImage needs the file's bytes as a Uint8Array or ArrayBuffer, got an object/,
  'decodeImage({ length: 1e9 })': /Uint8Array or ArrayBuffer/,
  'decodeImage(null)': /got null/,
  'parseSvg(42)': /SVG .* must be a string, got a number/,
  'parseSvg({})': /must be a string, got an object/,
  'parseSvg(null)': /must be a string, got null/,
  'parseSvg(new Uint8Array(4))': /must be a string, got a Uint8Array/,
  'progress callback throws': /The progress callback threw: boom from the callback/,
  'progress callback not a function': /progress callback must be a function.*got a number/,
  'path with 40,000 attributes': /thousands of attributes/,
  '8,000 CSS class rules': /style sheet has 8000 rules; the limit is 2000/,
  'texture from a 6x256 exemplar to 256²': undefined,
  'strokes 2e5 x 2e5, maxElements 1e9': /maxElements can be raised to at most 2000000/,
};

for (const [name, expr] of CASES) {
  test(`hostile: ${name}`, () => {
    const run = new Function('ps', `return ${expr};`);
    const want = WANT[name];
    if (want) {
      assert.throws(() => run(ps), (e) => e instanceof Error && !(e instanceof TypeError) && e.name !== 'InternalError' && want.test(e.message));
    } else {
      run(ps);
    }
    assert.ok(ps.synthesizeStrokes([{ points: [[0, 0], [4, 4]], width: 1 }, { points: [[20, 0], [24, 4]], width: 1 }], { width: 60, height: 10 }).strokes.length >= 2);
  });
}

test('geometry beyond range is left out with a warning, not flattened into billions of points', () => {
  const svg = '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100"><circle r="1e20"/><g transform="scale(1e15)"><circle r="3"/></g><rect width="5" height="5"/></svg>';
  const r = ps.parseSvgReport(svg, { tolerance: 1e-300 });
  assert.equal(r.strokes.length, 1);
  assert.ok(r.warnings.some((w) => /2 shape\(s\) lie beyond/.test(w)), r.warnings.join('; '));
});

test('an option set to null is named as null in the message', () => {
  const img = { width: 16, height: 16, data: new Uint8ClampedArray(16 * 16 * 4).fill(200) };
  assert.throws(() => ps.synthesizeTexture(img, { width: 16, height: 16, fuseSeams: null }), /fuseSeams.*got null, expected true or false|got null, expected true or false.*fuseSeams/);
});

test('an option set to undefined means its default', () => {
  const strokes = [{ points: [[0, 0], [4, 4]], width: 1 }, { points: [[20, 0], [24, 4]], width: 1 }];
  const a = ps.synthesizeStrokes(strokes, { width: 100, height: 10, seed: undefined, variation: undefined });
  const b = ps.synthesizeStrokes(strokes, { width: 100, height: 10 });
  assert.deepEqual(a.strokes, b.strokes);
});

test('a trap replaces the instance: the call says it was an internal error, the next call works', () => {
  const trapping = { ...glue, parseSvg: () => { throw new WebAssembly.RuntimeError('unreachable'); } };
  const e = engine(trapping, null, 'test');
  assert.throws(() => e.call('version', []), /called before the engine was loaded; `await init\(\)` first/);
  e.initSync({ module: readFileSync(new URL('../../pkg/wasm/full_bg.wasm', import.meta.url)) });
  for (let i = 0; i < 300; i++) {
    assert.throws(() => e.call('parseSvg', ['<svg/>']), (err) => err.name === 'InternalError' && /bug; the engine was restarted/.test(err.message));
  }
  assert.equal(e.restarts, 300);
  assert.equal(e.call('version', []), '0.1.0');
  assert.equal(ps.parseSvg('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 9 9"><rect width="2" height="2"/></svg>').length, 1);
});
