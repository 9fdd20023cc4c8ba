// Instantiates a wasm module of the package synchronously from the file beside it: the
// Node entries call this at import, so no `init()` and no fetch (also during SSR).
import { readFileSync } from 'node:fs';

export function load(initSync, name) {
  initSync({ module: readFileSync(new URL(`../wasm/${name}_bg.wasm`, import.meta.url)) });
}
