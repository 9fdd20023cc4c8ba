// The packed npm tarball in the frameworks web developers use, each with no configuration
// beyond what the package README documents, built for production, served, and opened in
// headless Chromium:
// - Next.js 16 (`next build` with its default bundler, Turbopack, then `next start`): a
//   route handler and a server component use patternsynth/vector on the server, a client
//   component runs init() and the worker client in the browser.
// - SvelteKit with adapter-node (`vite build`, then `node build`): a server load function
//   and onMount in the browser, with patternsynth once in "dependencies" and once in
//   "devDependencies" (adapter-node bundles those into the server output, which is then
//   deployed without node_modules/patternsynth).
// - Rollup 4 with @rollup/plugin-node-resolve: the README's recipe (its copy command,
//   the wasm's and the worker's URLs passed).
// - Parcel 2 (`parcel build index.html`, no configuration): a static page whose module
//   script imports patternsynth/vector and patternsynth/client, no URLs passed.
// - Astro 5 with @astrojs/node in standalone mode (output 'server'; `astro build`, then
//   `node dist/server/entry.mjs`): a page's frontmatter uses patternsynth/vector at
//   request time, its <script> runs the browser checks. Astro 6 and later need Node 22.
// - Next.js 15 (`next build` with its default bundler, webpack, then `next start`): the
//   Next.js 16 site (next/app) with Next.js 15, installed as the npm alias next15 and
//   given to the site as node_modules/next.
// The page's checks (browser-checks.js, copied into each site) are the bundler test's:
// strokes on the main thread, a texture through the worker client with progress, an
// abort that rejects with AbortError, a call after it that works, the codecs.
//
// The frameworks are installed by this test from package-lock.json beside it (`npm ci`)
// into node_modules/.cache/frameworks-<hash of the lockfile>/, once; each site gets a
// hard-linked copy of those node_modules plus the extracted tarball.
import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync, spawn } from 'node:child_process';
import { createHash } from 'node:crypto';
import {
  cpSync, existsSync, mkdirSync, mkdtempSync, readFileSync, readdirSync, renameSync, rmSync, writeFileSync,
} from 'node:fs';
import { createServer } from 'node:net';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { chromium } from 'playwright-core';
import { CHROMIUM } from '../browser/chromium.mjs';
import { serve } from '../../scripts/static-server.mjs';

const root = resolve(import.meta.dirname, '../..');
const here = import.meta.dirname;
const env = { ...process.env, NEXT_TELEMETRY_DISABLED: '1', ASTRO_TELEMETRY_DISABLED: '1' };

// A step that never settles must fail the test, not hold CI until its limit.
function within(ms, promise, what) {
  let timer;
  const late = new Promise((_, reject) => { timer = setTimeout(() => reject(new Error(`${what}: no answer in ${ms / 1000} s`)), ms); });
  return Promise.race([promise, late]).finally(() => clearTimeout(timer));
}

const tail = (text, lines = 60) => text.trim().split('\n').slice(-lines).join('\n');

// Every build and server runs in its own process group, killed whole; those still running
// when the file ends (a test that hit its time limit) are killed then.
const children = new Set();
function kill(child) {
  children.delete(child);
  try { process.kill(-child.pid, 'SIGKILL'); } catch { /* already gone */ }
}
process.on('exit', () => { for (const child of children) kill(child); });

/** Runs a command to its end (its whole process group killed after `ms`); resolves to
 *  its output, rejects with the output's end. */
function run(command, args, { cwd, ms = 300_000 }) {
  return new Promise((ok, fail) => {
    const child = spawn(command, args, { cwd, env, detached: true, stdio: ['ignore', 'pipe', 'pipe'] });
    children.add(child);
    let out = '';
    child.stdout.on('data', (d) => { out += d; });
    child.stderr.on('data', (d) => { out += d; });
    const timer = setTimeout(() => { out += `\n(killed after ${ms / 1000} s)`; kill(child); }, ms);
    child.on('error', fail);
    child.on('close', (code, signal) => {
      clearTimeout(timer);
      children.delete(child);
      if (code === 0) ok(out);
      else fail(new Error(`${[command, ...args].join(' ')} failed (${signal ?? `exit ${code}`}):\n${tail(out)}`));
    });
  });
}

function freePort() {
  return new Promise((ok, fail) => {
    const s = createServer().listen(0, '127.0.0.1', () => { const { port } = s.address(); s.close(() => ok(port)); }).on('error', fail);
  });
}

/** Starts a server (its own process group) and waits until `url` answers. */
async function start(command, args, { cwd, port, extraEnv = {} }) {
  const child = spawn(command, args, { cwd, env: { ...env, ...extraEnv }, detached: true, stdio: ['ignore', 'pipe', 'pipe'] });
  children.add(child);
  const server = { child, log: '', url: `http://127.0.0.1:${port}`, exited: null };
  child.stdout.on('data', (d) => { server.log += d; });
  child.stderr.on('data', (d) => { server.log += d; });
  child.on('exit', (code, signal) => { server.exited = signal ?? `exit ${code}`; });
  const deadline = Date.now() + 60_000;
  for (;;) {
    if (server.exited) throw new Error(`${[command, ...args].join(' ')} stopped (${server.exited}):\n${tail(server.log)}`);
    try {
      await within(5_000, fetch(server.url, { method: 'HEAD' }), 'the server');
      return server;
    } catch {
      if (Date.now() > deadline) { kill(child); throw new Error(`${[command, ...args].join(' ')} did not answer in 60 s:\n${tail(server.log)}`); }
      await new Promise((r) => setTimeout(r, 250));
    }
  }
}

// --- the frameworks, installed once per lockfile ------------------------------------

const lock = readFileSync(join(here, 'package-lock.json'));
const hash = createHash('sha256').update(lock).digest('hex').slice(0, 16);
const cacheRoot = join(root, 'node_modules/.cache');
const cache = join(cacheRoot, `frameworks-${hash}`);

function install() {
  if (existsSync(join(cache, 'installed'))) return;
  mkdirSync(cacheRoot, { recursive: true });
  // Installed beside, then renamed: a run stopped halfway leaves nothing that looks done.
  const fresh = mkdtempSync(join(cacheRoot, `frameworks-${hash}.part-`));
  try {
    cpSync(join(here, 'package.json'), join(fresh, 'package.json'));
    cpSync(join(here, 'package-lock.json'), join(fresh, 'package-lock.json'));
    execFileSync('npm', ['ci', '--prefer-offline', '--no-audit', '--no-fund', '--loglevel=error'], { cwd: fresh, stdio: 'pipe', timeout: 600_000 });
    writeFileSync(join(fresh, 'installed'), `${new Date().toISOString()}\n`);
    if (existsSync(join(cache, 'installed'))) {
      rmSync(fresh, { recursive: true, force: true }); // another run finished first
    } else {
      rmSync(cache, { recursive: true, force: true });
      renameSync(fresh, cache);
    }
  } catch (e) {
    rmSync(fresh, { recursive: true, force: true });
    throw new Error(`npm ci of tests/frameworks/package-lock.json failed: ${e.message}\n${tail(String(e.stderr ?? ''))}`);
  }
  // Installs for other lockfiles (900 MB each: two Next.js versions with their SWC
  // binaries, Parcel, Astro) are not kept.
  for (const name of readdirSync(cacheRoot)) {
    if (name.startsWith('frameworks-') && name !== `frameworks-${hash}` && !name.includes('.part-')) rmSync(join(cacheRoot, name), { recursive: true, force: true });
  }
}

// --- the sites -----------------------------------------------------------------------

let work;
let tarball;

/** A fresh copy of the site folder `name` (over a copy of the folder `base`, if given)
 *  with node_modules: the frameworks (hard links into the cache) and the tarball as
 *  node_modules/patternsynth. */
function site(name, checksInto, base) {
  const dir = mkdtempSync(join(work, `${name}-`));
  if (base) cpSync(join(here, base), dir, { recursive: true });
  cpSync(join(here, name), dir, { recursive: true });
  cpSync(join(here, 'browser-checks.js'), join(dir, checksInto, 'browser-checks.js'));
  try {
    execFileSync('cp', ['-al', join(cache, 'node_modules'), join(dir, 'node_modules')], { stdio: 'pipe' });
  } catch {
    rmSync(join(dir, 'node_modules'), { recursive: true, force: true });
    execFileSync('cp', ['-a', join(cache, 'node_modules'), join(dir, 'node_modules')], { stdio: 'pipe' });
  }
  const unpack = mkdtempSync(join(work, 'unpack-'));
  execFileSync('tar', ['-xzf', tarball, '-C', unpack]);
  renameSync(join(unpack, 'package'), join(dir, 'node_modules/patternsynth'));
  return dir;
}

// What the server code computes, as plain Node computes it from the same tarball.
let expected;

before(async () => {
  install();
  work = mkdtempSync(join(tmpdir(), 'patternsynth-frameworks-'));
  let name;
  try {
    name = execFileSync('npm', ['pack', join(root, 'pkg'), '--pack-destination', work, '--silent'], { encoding: 'utf8', stdio: 'pipe' }).trim().split('\n').at(-1);
  } catch (e) {
    throw new Error(`npm pack of pkg/ failed (is the package built?): ${tail(String(e.stderr || e.message), 20)}`);
  }
  tarball = join(work, name);
  const plain = join(work, 'plain');
  mkdirSync(join(plain, 'node_modules'), { recursive: true });
  execFileSync('tar', ['-xzf', tarball, '-C', join(plain, 'node_modules')]);
  renameSync(join(plain, 'node_modules/package'), join(plain, 'node_modules/patternsynth'));
  expected = JSON.parse(execFileSync(process.execPath, ['--input-type=module', '-e', `
    import { synthesizeStrokes, version } from 'patternsynth/vector';
    const row = [0, 1, 2].map((i) => ({ points: [[20 + i * 30, 20], [35 + i * 30, 35]], width: 2, stroke: '#224466' }));
    const out = synthesizeStrokes(row, { width: 200, height: 200, seed: 1 });
    console.log(JSON.stringify({ version: version(), strokes: out.strokes.length }));`], { cwd: plain, encoding: 'utf8' }));
  assert.ok(expected.strokes > 3, `plain Node made ${expected.strokes} strokes`);
}, { timeout: 900_000 });

after(() => {
  for (const child of children) kill(child);
  if (work) rmSync(work, { recursive: true, force: true });
});

/** Opens `url` in Chromium and waits for the page's window.result. */
async function browse(url, server) {
  const browser = await chromium.launch(CHROMIUM);
  try {
    const context = await browser.newContext();
    const page = await context.newPage();
    const errors = [];
    page.on('pageerror', (e) => errors.push(e.message));
    // Requests of the page and its workers that failed, for the message when a check fails.
    const failed = [];
    context.on('response', (r) => { if (r.status() >= 400) failed.push(`${r.status()} ${r.url()}`); });
    context.on('requestfailed', (r) => failed.push(`${r.failure()?.errorText} ${r.url()}`));
    const response = await page.goto(url, { timeout: 60_000 });
    assert.equal(response.status(), 200, `${url} answered ${response.status()}${server ? `\nserver log:\n${tail(server.log)}` : ''}`);
    // Frameworks run the checks after hydration, which may come after the load event.
    await within(120_000, page.waitForFunction(() => window.result !== undefined, null, { timeout: 0 }), 'the page\'s window.result');
    const result = await within(120_000, page.evaluate(() => window.result), 'the site\'s result');
    return { result, errors, failed };
  } finally {
    await browser.close();
  }
}

function check({ result, errors, failed }, server) {
  const log = `${failed.length ? `\nfailed requests:\n${failed.join('\n')}` : ''}${server ? `\nserver log:\n${tail(server.log)}` : ''}`;
  assert.deepEqual(errors, [], `page errors${log}`);
  assert.equal(result.error, undefined, `${result.error}${log}`);
  assert.ok(result.strokes > 200, `strokes: ${result.strokes}`);
  assert.deepEqual(result.texture, [64, 64, 'Uint8ClampedArray']);
  assert.ok(result.progress > 3 && result.lastProgress === 1, `progress events: ${result.progress}`);
  assert.equal(result.aborted, 'AbortError');
  assert.deepEqual(result.after, [48, 40]);
  assert.deepEqual(result.decoded, [8, 6]);
}

async function get(server, path) {
  const response = await within(60_000, fetch(server.url + path), `GET ${path}`);
  const body = await within(60_000, response.text(), `GET ${path}'s body`);
  assert.equal(response.status, 200, `GET ${path} answered ${response.status}: ${body.slice(0, 500)}\nserver log:\n${tail(server.log)}`);
  return body;
}

// --- the tests -------------------------------------------------------------------------

/** `next build`, then `next start`, of the site in `dir`: the route handler's JSON, the
 *  prerendered server component's number, the client component's browser checks. */
async function nextSite(dir) {
  const next = join(dir, 'node_modules/next/dist/bin/next');
  await run(process.execPath, [next, 'build'], { cwd: dir, ms: 300_000 });
  const port = await freePort();
  const server = await start(process.execPath, [next, 'start', '-p', String(port), '-H', '127.0.0.1'], { cwd: dir, port });
  try {
    const api = JSON.parse(await get(server, '/api/pattern'));
    assert.deepEqual(api, { ...expected, svg: true }, 'the route handler\'s JSON');
    const html = await get(server, '/');
    assert.match(html, new RegExp(`<span id="server-strokes">${expected.strokes}</span>`), 'the server component\'s number in the HTML');
    check(await browse(`${server.url}/`, server), server);
  } finally {
    kill(server.child);
  }
}

test('Next.js 16, next build (Turbopack) and next start: a route handler, a server component and a client component', { timeout: 900_000 }, async () => {
  await nextSite(site('next', 'app'));
});

test('Next.js 15, next build (webpack) and next start: the same route handler, server component and client component', { timeout: 900_000 }, async () => {
  // The Next.js 16 site's files with next15/package.json; Next.js 15 (the alias next15 in
  // the shared install, with its own nested dependencies) becomes node_modules/next.
  const dir = site('next15', 'app', 'next');
  rmSync(join(dir, 'node_modules/next'), { recursive: true });
  renameSync(join(dir, 'node_modules/next15'), join(dir, 'node_modules/next'));
  const { version } = JSON.parse(readFileSync(join(dir, 'node_modules/next/package.json'), 'utf8'));
  assert.match(version, /^15\./, 'node_modules/next of the Next.js 15 site');
  await nextSite(dir);
});

for (const field of ['dependencies', 'devDependencies']) {
  test(`SvelteKit + adapter-node, patternsynth in ${field}: vite build, then node build`, { timeout: 900_000 }, async () => {
    const dir = site('sveltekit', 'src/routes');
    const manifest = JSON.parse(readFileSync(join(dir, 'package.json'), 'utf8'));
    manifest[field] = { ...manifest[field], patternsynth: '*' };
    writeFileSync(join(dir, 'package.json'), `${JSON.stringify(manifest, null, 2)}\n`);
    await run(process.execPath, [join(dir, 'node_modules/vite/bin/vite.js'), 'build'], { cwd: dir, ms: 300_000 });
    // adapter-node bundled the devDependencies into build/: the server is what a deploy
    // of the build output alone runs, with no package folder to read files from.
    if (field === 'devDependencies') rmSync(join(dir, 'node_modules/patternsynth'), { recursive: true });
    const port = await freePort();
    const server = await start(process.execPath, ['build'], { cwd: dir, port, extraEnv: { PORT: String(port), HOST: '127.0.0.1' } });
    try {
      const html = await get(server, '/');
      assert.match(html, new RegExp(`<span id="server-strokes">${expected.strokes}</span>`), 'the load function\'s number in the HTML');
      check(await browse(`${server.url}/`, server), server);
    } finally {
      kill(server.child);
    }
  });
}

test('Rollup 4 + @rollup/plugin-node-resolve: the README recipe (files copied, the wasm\'s and worker\'s URLs passed)', { timeout: 900_000 }, async () => {
  const dir = site('rollup', '.');
  await run(process.execPath, [join(dir, 'node_modules/rollup/dist/bin/rollup'), '-c'], { cwd: dir, ms: 120_000 });
  // The copy command exactly as the packed README documents it, run by POSIX sh in the site
  // (dash on Debian, as npm scripts run it).
  const readme = readFileSync(join(dir, 'node_modules/patternsynth/README.md'), 'utf8');
  const recipe = [...readme.matchAll(/```(?:sh|bash|shell)\n([\s\S]*?)```/g)].map((m) => m[1]).find((b) => /\bcp\b/.test(b) && b.includes('node_modules/patternsynth'));
  assert.ok(recipe, 'the README has no shell block copying files out of node_modules/patternsynth');
  await run('sh', ['-eu', '-c', recipe], { cwd: dir, ms: 60_000 });
  cpSync(join(dir, 'index.html'), join(dir, 'dist/index.html'));
  const server = await serve(join(dir, 'dist'), 0);
  try {
    check(await browse(`http://127.0.0.1:${server.address().port}/`));
  } finally {
    server.close();
  }
});

test('Parcel 2, parcel build of a static page: init() and the worker client with no configuration', { timeout: 900_000 }, async () => {
  const dir = site('parcel', '.');
  await run(process.execPath, [join(dir, 'node_modules/parcel/lib/bin.js'), 'build', 'index.html', '--no-autoinstall'], { cwd: dir, ms: 300_000 });
  const server = await serve(join(dir, 'dist'), 0);
  try {
    check(await browse(`http://127.0.0.1:${server.address().port}/`));
  } finally {
    server.close();
  }
});

test('Astro 5 + @astrojs/node standalone: astro build, then node dist/server/entry.mjs (frontmatter on the server, a client script)', { timeout: 900_000 }, async () => {
  const dir = site('astro', 'src');
  await run(process.execPath, [join(dir, 'node_modules/astro/astro.js'), 'build'], { cwd: dir, ms: 300_000 });
  const port = await freePort();
  const server = await start(process.execPath, ['dist/server/entry.mjs'], { cwd: dir, port, extraEnv: { PORT: String(port), HOST: '127.0.0.1' } });
  try {
    const html = await get(server, '/');
    assert.match(html, new RegExp(`<span id="server-strokes">${expected.strokes}</span>`), 'the frontmatter\'s number in the HTML');
    check(await browse(`${server.url}/`, server), server);
  } finally {
    kill(server.child);
  }
});
