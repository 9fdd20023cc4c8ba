// A browser entry whose wasm cannot be had (a bundler that did not emit it, a
// single-page app answering a missing file with its index page, a host that is down)
// says which URL failed and where the README shows the way round. Its own process: the
// entry must not be loaded yet.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';

test('a wasm URL that fails names the URL and the README section that fixes it', async () => {
  const { createServer } = await import('node:http');
  // A missing file (404) and a single-page app's fallback (its index.html for any path).
  const server = createServer((req, res) => {
    if (req.url.startsWith('/missing')) return void res.writeHead(404).end('not found');
    res.writeHead(200, { 'Content-Type': 'text/html' }).end('<!doctype html><title>app</title>');
  });
  await new Promise((done) => server.listen(0, '127.0.0.1', done));
  const base = `http://127.0.0.1:${server.address().port}`;
  try {
    const { default: init, version } = await import('../../pkg/vector.js');
    const message = (url) => init(url).then(() => 'resolved', (e) => e.message);
    const missing = await message(`${base}/missing/vector_bg.wasm`);
    assert.match(missing, /could not fetch patternsynth\/vector's wasm from http:\/\/127\.0\.0\.1:\d+\/missing\/vector_bg\.wasm: HTTP 404\./);
    assert.match(missing, /"With a bundler" in the package README/);
    const page = await message(`${base}/app/vector_bg.wasm`);
    assert.match(page, /\/app\/vector_bg\.wasm is not patternsynth\/vector's wasm \(it starts with "<!do": a web page, probably a fallback page for a missing file\)/);
    assert.match(page, /"With a bundler"/);
    const unreachable = await message('http://127.0.0.1:9/vector_bg.wasm');
    assert.match(unreachable, /could not fetch patternsynth\/vector's wasm from http:\/\/127\.0\.0\.1:9\/vector_bg\.wasm \(/);
    // A failed init leaves the entry ready for one that works.
    await init(readFileSync('pkg/wasm/vector_bg.wasm'));
    assert.equal(version(), '0.1.0');
  } finally {
    server.close();
  }
});
