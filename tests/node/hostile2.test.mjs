// Hostile input, second round (issue 26, bench/hostile2.mjs): structure-level input
// through the built package. Each case gets a result or a clear Error, quickly; the
// instance keeps working; and after every case the engine's wasm memory is back within
// 64 MB of its start and its table of JS references within 1,024 slots of it.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import * as ps from '../../pkg/node/index.js';
import * as glue from '../../pkg/wasm/full.js';
import { engine, SPARE_BYTES, SPARE_REFERENCES } from '../../pkg/instance.js';
import { CASES } from '../../bench/hostile2.mjs';

// What each case must answer (a result when absent).
const WANT = {
  'classifyStrokes, 200,000 distinct strokes': /There are 200000 strokes; the limit is 50000/,
  'strokes: a Proxy array claiming length 1e9': /There are 1000000000 strokes; the limit is 50000/,
  'points: a Proxy array claiming length 1e9': /more than 5000000 points \(up to stroke 0\); the limit is 5000000/,
  '1 MB entity referenced 4,500 times': /entities expand to 4500\.\d MB of text \(`&big;`, 1\.0 MB, is used 4500 times\); the limit is 32\.0 MB/,
  'billion laughs (10 levels of 10)': /entities expand to 2861\.\d MB/,
  'progress callback calls the engine': /progress callback threw: patternsynth is busy: parseSvg\(\) was called while synthesizeStrokes\(\) is running/,
  'progress callbacks recursing to the stack limit': /patternsynth is busy/,
  'a 100 MB string': /The SVG is 100\.0 MB; the limit is 32\.0 MB/,
  'decodeImage of a detached ArrayBuffer': /image file's ArrayBuffer was detached.*bytes\.slice\(\)/,
  'decodeImage of a Uint8Array over a detached buffer': /image file's ArrayBuffer was detached/,
  'blend coefficient over a detached buffer': /coefficient map's ArrayBuffer was detached/,
  "exemplar pixels over a detached buffer": /image's data's ArrayBuffer was detached/,
  'synthesizeStrokes(strokes, {})': /`width` and `height` are required/,
  'a getter that throws': /Reading `seed` of the synthesis options threw: no seed for you/,
  'a Map as options': /got a Map: .*Object\.fromEntries/,
  'decodeImage of a Proxy of a Uint8Array': /decodeImage needs the file's bytes as a Uint8Array or ArrayBuffer/,
  'an option of the wrong type': /Invalid synthesis options: option `width`: got the string "wide", expected a number\./,
};

const state = () => ps.diagnostics();
const NORMAL = [{ points: [[0, 0], [4, 4]], width: 1 }, { points: [[20, 0], [24, 4]], width: 1 }];

// Cases about speed only (answered right before, in 97 s and 10.7 s): bench/hostile2.mjs
// times them; a test must not.
const BENCH_ONLY = new Set([
  'synthesizeStrokes: 50,000 distinct squares on a 3-unit grid to 2000 x 2000',
  'synthesizeStrokes: 50,000 overlapping squares scattered at random to 2000 x 2000',
  'suggestStrokes fill of [0, 0, 1e6, 1e6] after 50,000 strokes',
  // The second independent check's (23-37 s before, 1-8 s now; the synthesis's message
  // is tested natively, tests/vector_synthesis.rs).
  'classifyStrokes, 50,000 distinct strokes of 100 points',
  'synthesizeStrokes: 20,000 strokes of 250 points to 5000 x 5000, maxElements 2,000,000',
  'suggestStrokes fill after 2,000,000 strokes',
  'seamlessTile synthesis 2048 x 2048',
  'synthesizeTexture 256 x 256 to 2048 x 2048',
]);

for (const [name, expr] of CASES.filter(([name]) => !BENCH_ONLY.has(name))) {
  test(`hostile, second round: ${name}`, () => {
    const run = new Function('ps', `return ${expr};`);
    const want = WANT[name];
    const t0 = performance.now();
    if (want) {
      assert.throws(() => run(ps), (e) => e instanceof Error && !(e instanceof TypeError) && e.name !== 'InternalError' && want.test(e.message));
    } else {
      run(ps);
    }
    assert.ok(performance.now() - t0 < 10_000, 'within 10 s');
    const d = state();
    assert.ok(d.memoryBytes <= d.baselineBytes + SPARE_BYTES, `memory ${d.memoryBytes >> 20} MB over a start of ${d.baselineBytes >> 20} MB`);
    assert.ok(d.references <= d.baselineReferences + SPARE_REFERENCES + 128, `references ${d.references}, from ${d.baselineReferences}`);
    assert.ok(glue.bandsOpenJobs() <= 8, 'forgotten band jobs are closed');
    assert.ok(ps.synthesizeStrokes(NORMAL, { width: 60, height: 10 }).strokes.length >= 2);
    assert.equal(d.restarts, 0, 'no case restarts the engine');
  });
}

test('a class instance is read by its getters; a Set, a Promise and a typed array are refused by name', () => {
  const opts = new (class { get width() { return 90; } get height() { return 30; } get seed() { return 3; } })();
  const out = ps.synthesizeStrokes(NORMAL, opts);
  assert.deepEqual(out.strokes, ps.synthesizeStrokes(NORMAL, { width: 90, height: 30, seed: 3 }).strokes);
  assert.notDeepEqual(out.strokes, ps.synthesizeStrokes(NORMAL, { width: 90, height: 60, seed: 3 }).strokes);
  assert.throws(() => ps.synthesizeStrokes(NORMAL, new Set()), /got a Set/);
  assert.throws(() => ps.classifyStrokes(NORMAL, Promise.resolve({})), /got a Promise: await it first/);
  assert.throws(() => ps.synthesizeTexture({ width: 2, height: 2, data: new Uint8Array(16) }, new Float32Array(2)), /got a Float32Array: bytes are not options/);
  assert.throws(() => ps.parseSvg('<svg/>', new Proxy({}, { ownKeys() { throw new Error('no keys'); } })), /no keys/);
});

test('a stroke or a point that throws when read gives an error naming it', () => {
  const bad = [NORMAL[0], { get points() { throw new Error('points getter'); }, width: 1 }];
  assert.throws(() => ps.classifyStrokes(bad), /Reading `points` of the stroke 1 threw: points getter/);
  const point = [{ points: [[0, 0], new Proxy([], { get() { throw new Error('trap'); } })], width: 1 }];
  assert.throws(() => ps.classifyStrokes(point), /Reading point 1 of stroke 0 threw: trap/);
  assert.throws(() => ps.classifyStrokes([{ points: [[0, 0], 'xy'], width: 1 }]), /Stroke 0's point 1 must be \[x, y\] with two numbers, got a string/);
  assert.throws(() => ps.classifyStrokes([{ points: [[0, 0], [1, 1]], width: 1, stroke: 42 }]), /Invalid stroke 0: .*got 42, expected a string/);
});

test('a Proxy of bytes is refused by name; an option of the wrong type is named', () => {
  // The typed array's own methods throw (uncaught, through the glue) on a Proxy.
  assert.throws(() => ps.decodeImage(new Proxy(new Uint8Array(10), {})), /decodeImage needs the file's bytes as a Uint8Array or ArrayBuffer, got a Uint8Array that only inherits from one \(a Proxy\?\)/);
  assert.throws(() => ps.decodeImage(new Proxy(new ArrayBuffer(10), {})), /decodeImage needs the file's bytes/);
  const image = (data) => ({ width: 2, height: 2, data });
  assert.throws(() => ps.synthesizeTexture(image(new Proxy(new Uint8ClampedArray(16), {})), { width: 4, height: 4 }), /must be a Uint8Array or Uint8ClampedArray/);
  assert.throws(() => ps.synthesizeStrokes(NORMAL, { width: 'wide', height: 100 }), (e) => /option `width`: got the string "wide"/.test(e.message) && !/Error: /.test(e.message));
  assert.equal(ps.decodeImage(ps.encodePng(image(new Uint8ClampedArray(16).fill(200)))).width, 2);
});

test('a call that grows memory past 64 MB gives it back before the next call', () => {
  const before = state();
  assert.throws(() => ps.parseSvg(`<svg>${' '.repeat(100 << 20)}</svg>`), /limit is 32\.0 MB/);
  const after = state();
  assert.ok(after.renewals > before.renewals, 'the instance was renewed');
  assert.ok(after.memoryBytes <= after.baselineBytes + SPARE_BYTES);
  const im = { width: 16, height: 16, data: Uint8Array.from({ length: 16 * 16 * 4 }, (_, i) => (i * 2654435761) >>> 24) };
  assert.equal(ps.synthesizeTexture(im, { width: 32, height: 32, seed: 2 }).width, 32);
});

test('5,000 failing calls with throwing getters and proxies leave the reference table bounded', () => {
  const start = state().references;
  const bad = [{ get width() { throw new Error('getter'); }, height: 10 }, new Proxy({}, { get() { throw new Error('get'); } })];
  for (let i = 0; i < 5000; i++) assert.throws(() => ps.synthesizeStrokes(NORMAL, bad[i % 2]), /threw/);
  assert.ok(state().references <= Math.max(start, state().baselineReferences) + SPARE_REFERENCES + 128, `${state().references} references`);
});

test('an exception that unwinds through the module restarts it; the same exception is thrown', () => {
  const thrown = new TypeError('from page code');
  const unwinding = { ...glue, parseSvg: () => { throw thrown; } };
  const e = engine(unwinding, null, 'test');
  e.initSync({ module: readFileSync(new URL('../../pkg/wasm/full_bg.wasm', import.meta.url)) });
  assert.throws(() => e.call('parseSvg', ['<svg/>']), (err) => err === thrown);
  assert.equal(e.restarts, 1);
  assert.throws(() => e.call('classifyStrokes', [[], {}]), /no strokes/);
  assert.equal(e.restarts, 1, 'an error the module returns is not an unwinding');
});

test('a whole-number option beyond its range says the range', () => {
  const svg = '<svg xmlns="http://www.w3.org/2000/svg"><rect width="5" height="5"/></svg>';
  assert.throws(() => ps.parseSvg(svg, { maxPoints: 2 ** 53 - 1 }), /option `maxPoints`: invalid value: integer `9007199254740991`, expected a whole number from 0 to 4294967295\./);
  assert.throws(() => ps.synthesizeStrokes(NORMAL, { width: 10, height: 10, seed: -1 }), /option `seed`: got -1, expected a whole number from 0 to 9007199254740991\./);
});
