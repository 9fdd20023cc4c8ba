// Instantiates a wasm module of the package synchronously at import (no `init()`, no
// fetch, also during SSR) from a copy embedded in the package's JS: `embedded/<name>.js`
// (written by the build) holds the module gzipped, as base64. Reading the .wasm file
// beside the entry broke as soon as the entry was bundled: Turbopack resolved a
// computed `new URL()` to one file for every entry and handed `readFileSync` its own
// URL class, and SvelteKit's adapter-node bundles devDependencies into chunks with no
// wasm beside them. A JS module every bundler carries along; decoding costs a few ms.
import { gunzipSync } from 'node:zlib';

export function load(initSync, base64) {
  initSync({ module: gunzipSync(Buffer.from(base64, 'base64')) });
}
