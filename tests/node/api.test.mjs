// The built package under Node: the API contract of SPEC section 4 (vector part),
// clear errors for bad input, and that the package resolves by name from Node and
// from a bundler.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, mkdirSync, readFileSync, symlinkSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import * as ps from '../../pkg/node/index.js';

const grid = () => {
  const s = [];
  for (let i = 0; i < 5; i++) for (let j = 0; j < 5; j++) s.push({ points: [[20 + i * 30, 20 + j * 30], [28 + i * 30, 30 + j * 30]], width: 2, stroke: '#223344' });
  return s;
};

test('synthesizeStrokes returns strokes, classes and valid SVG', () => {
  const seen = [];
  const r = ps.synthesizeStrokes(grid(), { width: 300, height: 300, seed: 3 }, (f) => { seen.push(f); });
  assert.ok(r.strokes.length >= 90 && r.strokes.length <= 130, `${r.strokes.length}`);
  assert.equal(r.classes.length, r.strokes.length);
  assert.equal(r.classification.count, 1);
  assert.match(r.svg, /^<svg xmlns="http:\/\/www.w3.org\/2000\/svg"/);
  // A path per stroke, or a use of one defined once (translated copies).
  const body = r.svg.replace(/<defs>[\s\S]*<\/defs>/, '');
  assert.equal((body.match(/<(path|use) /g) || []).length, r.strokes.length);
  assert.ok(r.svg.length < 0.5 * r.strokes.length * 120, `${r.svg.length} bytes for ${r.strokes.length} strokes: copies are uses`);
  assert.equal(r.strokes[0].stroke, '#223344');
  assert.ok(seen.length > 3 && seen.at(-1) === 1, 'progress reported to 1');
  // The SVG reads back through our own importer.
  assert.equal(ps.parseSvg(r.svg).length, r.strokes.length);
});

test('strokeTile returns a seamless tile of the drawing\'s repeat', () => {
  const t = ps.strokeTile(grid(), { repeats: 3, seed: 2 });
  assert.ok(Math.abs(t.width - 90) < 1e-6 && Math.abs(t.height - 90) < 1e-6, `${t.width} x ${t.height}`);
  assert.equal(t.sites, 9);
  assert.match(t.svg, /width="90" height="90" viewBox="0 0 90 90"/);
  assert.equal(ps.parseSvg(t.svg).length, t.strokes.length);
  assert.deepEqual(t.periods.map((p) => p.map((v) => Math.round(v))), [[30, 0], [0, 30]]);
  assert.throws(() => ps.strokeTile(grid(), { repeat: 2 }), /unknown option `repeat`/);
  assert.throws(() => ps.strokeTile([grid()[0], { points: [[90, 10], [95, 12]], width: 1 }], {}), /regular repeat/);
});

test('returning false from the progress callback cancels', () => {
  assert.throws(() => ps.synthesizeStrokes(grid(), { width: 3000, height: 3000 }, () => false), /Cancelled/);
});

test('bad input throws Errors a person understands', () => {
  const cases = [
    [() => ps.synthesizeStrokes([], { width: 10, height: 10 }), /no strokes/],
    [() => ps.synthesizeStrokes('nope', { width: 10, height: 10 }), /array/],
    [() => ps.synthesizeStrokes([{ points: [[0, 0]], width: 1, stroke: 'red' }], { width: 10, height: 10 }), /#rrggbb/],
    [() => ps.synthesizeStrokes([{ points: [[NaN, 0]], width: 1 }], { width: 10, height: 10 }), /finite|number/],
    [() => ps.synthesizeStrokes(grid(), { width: 10, height: 10, widht: 4 }), /unknown option `widht`/],
    [() => ps.synthesizeStrokes(grid(), { width: -1, height: 10 }), /positive/],
    [() => ps.synthesizeStrokes(grid(), { width: 1e8, height: 1e8 }), /limit/],
    [() => ps.parseSvg('<svg><g></svg>'), /Could not read the SVG/],
    [() => ps.parseSvg('<svg xmlns="http://www.w3.org/2000/svg"/>', { tolerance: 0 }), /tolerance/],
  ];
  for (const [fn, want] of cases) {
    assert.throws(fn, (e) => e instanceof Error && want.test(e.message), String(want));
  }
});

test('classifyStrokes proposes tolerances and takes given ones', () => {
  const strokes = [...grid(), ...grid().map((s) => ({ ...s, stroke: '#dd2222' }))];
  const auto = ps.classifyStrokes(strokes);
  assert.equal(auto.count, 2);
  const merged = ps.classifyStrokes(strokes, { colorTolerance: 500 });
  assert.equal(merged.count, 1);
  assert.equal(merged.tolerances.color, 500);
});

test('strokes given without paint are drawn with a black pen', () => {
  // (A new user's trial: { points, width } came back as an SVG of invisible paths.)
  const strokes = [0, 1, 2, 3].map((i) => ({ points: [[10 + 30 * i, 10], [20 + 30 * i, 30]], width: 2 }));
  const r = ps.synthesizeStrokes(strokes, { width: 200, height: 60, variation: false });
  assert.ok(r.strokes.length > 4 && r.strokes.every((s) => s.stroke === '#000000'));
  assert.match(r.svg, /stroke="#000000"/);
  assert.doesNotMatch(r.svg, /stroke="none"/);
});

test('three petals each drawn as two arcs synthesize into rosettes of whole petals', () => {
  // (Issue 27: they became a scatter of 507 loose arcs.) Arcs from the centre (400, 250)
  // 110 out, bulging either side, a little wobble.
  const arc = (theta, bulge) => ({
    width: 3,
    points: Array.from({ length: 17 }, (_, k) => {
      const t = k / 16, along = 110 * t, across = -bulge * 110 * 4 * t * (1 - t) + ((k % 3) - 1) * 0.6;
      return [400 + along * Math.cos(theta) - across * Math.sin(theta), 250 + along * Math.sin(theta) + across * Math.cos(theta)];
    }),
  });
  const strokes = [0, 1, 2].flatMap((k) => [arc((k * Math.PI) / 4, 0.18), arc((k * Math.PI) / 4, -0.18)]);
  const r = ps.synthesizeStrokes(strokes, { width: 800, height: 600 });
  assert.equal(r.structure, 'ring');
  // Each rosette's arcs begin at its centre: sixteen a rosette (those cut by the edge
  // fewer), both arcs of every petal.
  const centres = new Map();
  for (const s of r.strokes) {
    const key = `${Math.round(s.points[0][0] / 20)},${Math.round(s.points[0][1] / 20)}`;
    centres.set(key, (centres.get(key) ?? 0) + 1);
  }
  const full = [...centres.values()].filter((n) => n === 16).length;
  assert.ok(full >= 2, `rosettes of ${[...centres.values()]} arcs`);
});

test('fill-only shapes survive the whole trip', () => {
  const svg = '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">' +
    [0, 1, 2, 3].map((i) => `<rect x="${10 + i * 20}" y="10" width="8" height="8" fill="#00aa55" fill-opacity="0.5"/>`).join('') + '</svg>';
  const strokes = ps.parseSvg(svg);
  assert.equal(strokes[0].stroke, null);
  const r = ps.synthesizeStrokes(strokes, { width: 200, height: 40, variation: false });
  assert.ok(r.strokes.every((s) => s.fill === '#00aa55' && s.stroke === null && s.fillOpacity === 0.5));
  assert.match(r.svg, /fill="#00aa55" fill-opacity="0.5" stroke="none"/);
});

test('the package resolves by name in Node and in a bundler', () => {
  const dir = mkdtempSync(join(tmpdir(), 'patternsynth-'));
  mkdirSync(join(dir, 'node_modules'));
  symlinkSync(resolve('pkg'), join(dir, 'node_modules', 'patternsynth'), 'dir');
  writeFileSync(join(dir, 'use.mjs'), `import { version, synthesizeStrokes } from 'patternsynth';
    const r = synthesizeStrokes([{ points: [[0,0],[5,5]], width: 1, stroke: '#000000' }, { points: [[20,0],[25,5]], width: 1, stroke: '#000000' }], { width: 100, height: 20 });
    console.log(version(), r.strokes.length);`);
  const out = execFileSync(process.execPath, ['use.mjs'], { cwd: dir, encoding: 'utf8' }).trim();
  assert.match(out, /^0\.1\.0 \d+$/);

  // A browser bundle: the wasm is referenced as an asset URL, no Node built-ins.
  writeFileSync(join(dir, 'entry.js'), `import init, { synthesizeStrokes } from 'patternsynth';
    import { PatternSynthClient } from 'patternsynth/client';
    export { init, synthesizeStrokes, PatternSynthClient };`);
  const esbuild = resolve('node_modules/.bin/esbuild');
  execFileSync(esbuild, ['entry.js', '--bundle', '--format=esm', '--platform=browser', '--outfile=bundle.js', '--loader:.wasm=file'], { cwd: dir });
  const bundle = readFileSync(join(dir, 'bundle.js'), 'utf8');
  assert.match(bundle, /full_bg\.wasm/);
  assert.doesNotMatch(bundle, /node:fs/);

  // Types are shipped.
  const dts = readFileSync('pkg/patternsynth.d.ts', 'utf8') + readFileSync('pkg/vector.d.ts', 'utf8') + readFileSync('pkg/types.d.ts', 'utf8');
  for (const name of ['parseSvg', 'synthesizeStrokes', 'classifyStrokes', 'interface Stroke']) assert.ok(dts.includes(name), name);
});

test('the entry points are declared once: every entry, its wasm glue and api.js agree', async () => {
  const { METHODS, BAND_EXPORTS } = await import('../../pkg/api.js');
  const names = (module) => Object.keys(METHODS).filter((k) => !METHODS[k].module || module.includes(METHODS[k].module)).sort();
  // The glue also has the worker protocol of banded synthesis, which entries carry as `bands`.
  const glue = (module) => [...names(module), ...(module.includes('texture') ? BAND_EXPORTS : [])].sort();
  const own = ['default', 'initSync', 'restarts', 'diagnostics', 'bands', 'simd'];
  const exported = (m, extra = []) => Object.keys(m).filter((k) => ![...own, ...extra].includes(k)).sort();
  const glueNames = (m) => Object.keys(m).filter((k) => !['default', 'initSync', 'start', '__wbg_reset', '__wbg_takeReturned'].includes(k)).sort();
  assert.deepEqual(exported(ps, ['initCodecs', 'initCodecsSync']), Object.keys(METHODS).sort());
  assert.deepEqual(Object.keys(ps.bands).sort(), ['close', 'open', 'run']);
  assert.deepEqual(glueNames(await import('../../pkg/wasm/full.js')), glue(['vector', 'texture']));
  for (const entry of ['vector', 'texture', 'codec']) {
    assert.deepEqual(exported(await import(`../../pkg/node/${entry}.js`)), names([entry]), entry);
    assert.deepEqual(glueNames(await import(`../../pkg/wasm/${entry}.js`)), glue([entry]), `${entry} glue`);
  }
  const { PatternSynthClient } = await import('../../pkg/client.js');
  for (const name of Object.keys(METHODS)) assert.equal(typeof PatternSynthClient.prototype[name], 'function', name);
});

test('each engine entry works alone in Node, and the browser entry asks for init first', async () => {
  const vector = await import('../../pkg/node/vector.js');
  const texture = await import('../../pkg/node/texture.js');
  const codec = await import('../../pkg/node/codec.js');
  assert.equal(vector.parseSvg('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 9 9"><rect width="2" height="2"/></svg>').length, 1);
  const img = { width: 16, height: 16, data: new Uint8ClampedArray(16 * 16 * 4).fill(200) };
  assert.equal(texture.synthesizeTexture(img, { width: 20, height: 20, seed: 1 }).width, 20);
  assert.equal(codec.decodeImage(codec.encodePng(img)).width, 16);
  // The browser entries, not initialised (in a process of their own: the Node entries
  // initialise the same modules).
  const call = (entry, expr) => execFileSync(process.execPath, ['--input-type=module', '-e',
    `import * as m from './pkg/${entry}.js'; try { ${expr}; } catch (e) { console.log(e.message); }`], { encoding: 'utf8' });
  assert.match(call('texture', 'm.seamlessTile({})'), /patternsynth\/texture: seamlessTile\(\) was called before the engine was loaded; `await init\(\)` first/);
  assert.match(call('patternsynth', 'm.decodeImage(new Uint8Array(4))'), /decodeImage\(\) was called before the engine was loaded; `await initCodecs\(\)` first/);
});

test('the option types declare exactly the options the engine reads', () => {
  const dts = readFileSync('pkg/types.d.ts', 'utf8').replace(/\/\*\*[\s\S]*?\*\//g, '');
  // The keys of an interface, with those of the interface it extends.
  const keys = (name) => {
    const m = dts.match(new RegExp(`interface ${name}(?: extends (\\w+))? \\{([^}]*)\\}`));
    assert.ok(m, name);
    const own = [...m[2].matchAll(/(\w+)\??:/g)].map((k) => k[1]);
    return [...(m[1] ? keys(m[1]) : []), ...own].sort();
  };
  // The engine names the options it knows when it meets one it does not.
  const known = (call) => {
    try {
      call({ notAnOption: 1 });
    } catch (e) {
      const m = e.message.match(/unknown option `notAnOption` \(expected one of ([^)]*)\)/);
      assert.ok(m, e.message);
      return m[1].split(', ').sort();
    }
    assert.fail('accepted an unknown option');
  };
  const img = { width: 8, height: 8, data: new Uint8Array(256) };
  const grid = [{ points: [[0, 0], [4, 4]], width: 1, stroke: '#000000' }];
  // (Options read by hand beside those serde reads, images and the blend's
  // coefficient, are named too: a misspelt `sampleMask` once listed every option but it.)
  const cases = [
    ['ParseSvgOptions', (o) => ps.parseSvg('<svg xmlns="http://www.w3.org/2000/svg"/>', o)],
    ['ClassifyOptions', (o) => ps.classifyStrokes(grid, o)],
    ['StrokeOptions', (o) => ps.synthesizeStrokes(grid, { width: 9, height: 9, ...o })],
    ['TileOptions', (o) => ps.strokeTile(grid, o)],
    ['TextureOptions', (o) => ps.synthesizeTexture(img, { width: 9, height: 9, ...o })],
    ['SeamlessOptions', (o) => ps.seamlessTile(img, o)],
    ['InpaintOptions', (o) => ps.inpaintTexture(img, img, o)],
    ['StyleOptions', (o) => ps.transferStyle(img, img, o)],
  ];
  for (const [name, call] of cases) assert.deepEqual(keys(name), known(call), name);
  // Blend options: the texture options serde reads but the layout (which blends refuse).
  const blendKnown = known((o) => ps.blendTextures(img, img, { width: 9, height: 9, ...o })).filter((k) => k !== 'keepLayout' && k !== 'fuseSeams');
  assert.deepEqual(keys('BlendOptions'), blendKnown);
  assert.throws(() => ps.blendTextures(img, img, { width: 9, height: 9, keepLayout: true }), /keepLayout applies to synthesizeTexture/);
  assert.throws(() => ps.blendTextures(img, img, { width: 9, height: 9, fuseSeams: true }), /fuseSeams applies to synthesizeTexture and seamlessTile/);
  assert.equal(ps.blendTextures(img, img, { width: 9, height: 9, fuseSeams: false }).width, 9);
});

test('seamlessTile refuses a clear image, and says what a strip loses to a square', () => {
  const clear = { width: 16, height: 16, data: new Uint8Array(16 * 16 * 4) };
  for (const method of ['synthesis', 'etfmcm', 'mend']) {
    assert.throws(() => ps.seamlessTile(clear, { method }), /fully transparent: there is nothing in it to tile/, method);
  }
  const data = new Uint8Array(9 * 300 * 4).map((_, i) => (i % 4 === 3 ? 255 : (i * 37) % 256));
  const r = ps.seamlessTile({ width: 9, height: 300, data }, { method: 'etfmcm' });
  assert.match(r.warnings.join(' '), /centre 9x9, 3% of it \(tiles are square; method 'synthesis' uses the whole image\)/);
});

test('the packed package holds every file its modules import or fetch', async () => {
  const { execFileSync } = await import('node:child_process');
  const { readFileSync } = await import('node:fs');
  const { dirname, join, normalize } = await import('node:path');
  const pkg = new URL('../../pkg/', import.meta.url).pathname;
  const [{ files }] = JSON.parse(execFileSync('npm', ['pack', pkg, '--dry-run', '--json'], { encoding: 'utf8' }));
  const shipped = new Set(files.map((f) => f.path));
  const missing = [];
  for (const file of shipped) {
    if (!/\.(js|d\.ts|d\.cts)$/.test(file)) continue;
    const text = readFileSync(join(pkg, file), 'utf8');
    const refs = [...text.matchAll(/(?:from\s+|import\(\s*|new URL\(\s*)['"`](\.{1,2}\/[^'"`$]+)['"`]/g)].map((m) => m[1]);
    for (const ref of refs) {
      let target = normalize(join(dirname(file), ref));
      if (/\.d\.c?ts$/.test(file)) target = target.replace(/\.js$/, '.d.ts').replace(/\.cjs$/, '.d.cts');
      if (!shipped.has(target)) missing.push(`${file} -> ${ref}`);
    }
  }
  assert.deepEqual(missing, []);
});
