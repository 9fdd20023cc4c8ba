// Adds `__wbg_reset()` to a wasm-bindgen web-target glue module, so that the package
// can drop an instance after a trap and instantiate the module afresh (instance.js).
// Fails loudly if the glue no longer has the shape this relies on.
//   node scripts/patch-glue.mjs pkg/wasm/full.js
import { readFileSync, writeFileSync } from 'node:fs';

for (const file of process.argv.slice(2)) {
  const src = readFileSync(file, 'utf8');
  if (!/^let wasmModule, wasmInstance, wasm;$/m.test(src) || !/\nfunction initSync\(module\) \{\n\s+if \(wasm !== undefined\) return wasm;/.test(src)) {
    throw new Error(`${file}: the wasm-bindgen glue changed shape; update scripts/patch-glue.mjs`);
  }
  writeFileSync(file, `${src}
/** Forgets the instance (after a trap), so that initSync makes a new one. */
export function __wbg_reset() {
    wasm = undefined;
    wasmInstance = undefined;
}
`);
}
