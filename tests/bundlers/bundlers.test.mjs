// The packed npm tarball in a small site (site/main.js) built for production by Vite,
// webpack 5 and esbuild, opened in headless Chromium: strokes on the main thread, a
// texture through the worker client with progress, an abort that rejects with
// AbortError, a call after the abort that works, and the codecs loaded on demand. Vite and webpack need nothing
// (the client builds its worker in the form they bundle); esbuild bundles no workers,
// so the site serves the package's files and passes the worker's URL (README recipe).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { cpSync, mkdirSync, mkdtempSync, readFileSync, readdirSync, renameSync, statSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { chromium } from 'playwright-core';
import { CHROMIUM } from '../browser/chromium.mjs';
import { serve } from '../../scripts/static-server.mjs';

const root = resolve(import.meta.dirname, '../..');
const bin = (name) => join(root, 'node_modules/.bin', name);

/** A fresh site folder with the tarball installed as node_modules/patternsynth. */
function site() {
  const work = mkdtempSync(join(tmpdir(), 'patternsynth-site-'));
  const tgz = execFileSync('npm', ['pack', join(root, 'pkg'), '--pack-destination', work, '--silent'], { encoding: 'utf8' }).trim().split('\n').at(-1);
  cpSync(join(import.meta.dirname, 'site'), join(work, 'site'), { recursive: true });
  mkdirSync(join(work, 'site/node_modules'));
  execFileSync('tar', ['-xzf', join(work, tgz), '-C', join(work, 'site/node_modules')]);
  renameSync(join(work, 'site/node_modules/package'), join(work, 'site/node_modules/patternsynth'));
  return work;
}

// A step that never settles (a worker that never answers, a response body Chromium never
// hands over) must fail the test, not hold CI until its limit: once a run of this file
// sat 30 minutes in one of them.
function within(ms, promise, what) {
  let timer;
  const late = new Promise((_, reject) => { timer = setTimeout(() => reject(new Error(`${what}: no answer in ${ms / 1000} s`)), ms); });
  return Promise.race([promise, late]).finally(() => clearTimeout(timer));
}

async function open(dir) {
  const server = await serve(dir, 0);
  const browser = await chromium.launch(CHROMIUM);
  try {
    const context = await browser.newContext();
    const page = await context.newPage();
    const errors = [];
    const wasm = new Set();
    page.on('pageerror', (e) => errors.push(e.message));
    // Requests of the page and of its workers: which wasm modules the site loaded.
    // Bundlers rename them (webpack: a content hash), so they are told apart by size:
    // the size of the served file the URL names. Not by the response's body: Chromium
    // never hands over the body of a fetch whose worker was terminated (the abort step),
    // and a CI run waited on it.
    const bySize = new Map(readdirSync(join(root, 'pkg/wasm')).filter((f) => f.endsWith('.wasm')).map((f) => [statSync(join(root, 'pkg/wasm', f)).size, f]));
    context.on('response', (r) => {
      const path = decodeURIComponent(new URL(r.url()).pathname);
      if (!path.endsWith('.wasm')) return;
      let size;
      try { size = statSync(join(dir, path)).size; } catch { size = undefined; }
      wasm.add(bySize.get(size) ?? r.url());
    });
    await page.goto(`http://127.0.0.1:${server.address().port}/`, { timeout: 60_000 });
    const result = await within(120_000, page.evaluate(() => window.result), 'the site\'s result');
    return { result, errors, wasm: [...wasm].sort() };
  } finally {
    await browser.close();
    server.close();
  }
}

/** Whether some file under `dir` holds exactly the bytes of the package's `file`. */
function emitted(dir, file) {
  const want = readFileSync(join(work, 'site/node_modules/patternsynth', file));
  const walk = (d) => readdirSync(d, { withFileTypes: true }).some((e) => (e.isDirectory()
    ? walk(join(d, e.name))
    : statSync(join(d, e.name)).size === want.length && readFileSync(join(d, e.name)).equals(want)));
  return walk(dir);
}

function check({ result, errors, wasm }, dir) {
  assert.deepEqual(errors, []);
  assert.equal(result.error, undefined, result.error);
  assert.ok(result.strokes > 200, `strokes: ${result.strokes}`);
  assert.deepEqual(result.texture, [64, 64, 'Uint8ClampedArray']);
  assert.ok(result.progress > 3 && result.lastProgress === 1, `progress events: ${result.progress}`);
  assert.equal(result.aborted, 'AbortError');
  assert.deepEqual(result.after, [48, 40]);
  assert.deepEqual(result.decoded, [8, 6]);
  // The page's own module is the vector one; the worker loads the texture one for the
  // texture calls (never the full or vector module), then the
  // codecs when first asked (names as the bundler emitted them, hashes aside).
  if (!wasm) return;
  console.log(`wasm loaded: ${wasm.join(', ')}`);
  assert.equal(wasm.length, 3, wasm.join(', '));
  for (const name of ['vector', 'texture', 'codec']) assert.ok(wasm.some((w) => w.includes(name)), `${name}: ${wasm.join(', ')}`);
  // Chromium runs SIMD, so the SIMD build is the one loaded; the scalar build is in the
  // output all the same, for browsers without SIMD.
  assert.ok(!wasm.some((w) => w.includes('scalar')), `the scalar build was loaded: ${wasm.join(', ')}`);
  assert.ok(emitted(dir, 'wasm/texture_scalar_bg.wasm'), 'the scalar texture module is in the output');
}

const work = site();

test('Vite production build: the worker client works with no configuration', async () => {
  execFileSync(bin('vite'), ['build', join(work, 'site'), '--outDir', join(work, 'dist-vite'), '--emptyOutDir', '--logLevel', 'warn']);
  check(await open(join(work, 'dist-vite')), join(work, 'dist-vite'));
});

test('webpack 5 production build: the worker client works with no configuration', async () => {
  execFileSync(bin('webpack'), ['--config', join(import.meta.dirname, 'webpack.config.cjs'), '--env', `work=${work}`], { stdio: 'pipe' });
  writeFileSync(join(work, 'dist-webpack/index.html'), readFileSync(join(work, 'site/index.html'), 'utf8').replace('type="module" ', ''));
  check(await open(join(work, 'dist-webpack')), join(work, 'dist-webpack'));
});

test('esbuild bundle: the package files served beside it, the worker passed by URL', async () => {
  const out = join(work, 'dist-esbuild');
  execFileSync(bin('esbuild'), [join(work, 'site/main.js'), '--bundle', '--format=esm', `--outfile=${join(out, 'main.js')}`, '--log-level=warning']);
  // Exactly the files the package README's copy command copies.
  const from = join(work, 'site/node_modules/patternsynth');
  for (const f of ['worker.js', 'vector.js', 'texture.js', 'codec.js', 'api.js', 'render.js', 'restyle.js', 'instance.js', 'flat.js', 'simd.js',
    ...['vector', 'texture', 'codec'].flatMap((m) => [`wasm/${m}.js`, `wasm/${m}_bg.wasm`]), 'wasm/texture_scalar_bg.wasm']) {
    mkdirSync(join(out, 'patternsynth/wasm'), { recursive: true });
    cpSync(join(from, f), join(out, 'patternsynth', f));
  }
  // The recipe: init() with the wasm's URL, the client with the worker's URL.
  writeFileSync(join(out, 'index.html'), `<!doctype html><meta charset="utf-8">
    <script>globalThis.wasmUrl = new URL('./patternsynth/wasm/vector_bg.wasm', location.href);
      globalThis.makeClient = (Client) => new Client(new URL('./patternsynth/worker.js', location.href));</script>
    <script type="module" src="./main.js"></script>`);
  check(await open(out), out);
});

test('a TypeScript consumer type-checks with tsc --strict against the shipped types', () => {
  cpSync(join(import.meta.dirname, 'site/consumer.ts'), join(work, 'site/consumer.ts'));
  execFileSync(bin('tsc'), ['--strict', '--noEmit', '--target', 'es2022', '--module', 'esnext', '--moduleResolution', 'bundler',
    '--lib', 'es2022,dom', join(work, 'site/consumer.ts')], { stdio: 'pipe' });
});

test('Node-only TypeScript (no DOM library) and CommonJS TypeScript (module node16) type-check; the CommonJS output runs', () => {
  for (const f of ['node-only.ts', 'commonjs.cts']) cpSync(join(import.meta.dirname, 'site', f), join(work, 'site', f));
  const tsc = (...args) => execFileSync(bin('tsc'), ['--strict', '--target', 'es2022', '--module', 'node16', '--moduleResolution', 'node16',
    '--lib', 'es2022', '--types', 'node', '--typeRoots', join(root, 'node_modules/@types'), ...args], { stdio: 'pipe', cwd: join(work, 'site') });
  tsc('--noEmit', join(work, 'site/node-only.ts'));
  tsc('--outDir', join(work, 'site/out'), join(work, 'site/commonjs.cts'));
  const printed = execFileSync(process.execPath, [join(work, 'site/out/commonjs.cjs')], { encoding: 'utf8', cwd: join(work, 'site') });
  assert.match(printed, /^0\.1\.0 \d+ function$/m);
});

test('Vite dev server: the same site works unbuilt', async () => {
  const { createServer } = await import('vite');
  const server = await createServer({ root: join(work, 'site'), logLevel: 'warn', server: { port: 0, host: '127.0.0.1' } });
  await server.listen();
  const browser = await chromium.launch(CHROMIUM);
  try {
    const page = await browser.newPage();
    const errors = [];
    page.on('pageerror', (e) => errors.push(e.message));
    await page.goto(`http://127.0.0.1:${server.httpServer.address().port}/`, { timeout: 60_000 });
    const result = await within(120_000, page.evaluate(() => window.result), 'the site\'s result');
    check({ result, errors });
  } finally {
    await browser.close();
    await server.close();
  }
});
