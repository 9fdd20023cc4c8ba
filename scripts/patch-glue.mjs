// Adds `__wbg_reset()` to a wasm-bindgen web-target glue module, so that the package
// can drop an instance after a trap and instantiate the module afresh (instance.js),
// and `__wbg_takeReturned()`, which tells an error the module returned from an
// exception that unwound through it.
// Fails loudly if the glue no longer has the shape this relies on.
//   node scripts/patch-glue.mjs pkg/wasm/full.js
import { readFileSync, writeFileSync } from 'node:fs';

for (const file of process.argv.slice(2)) {
  const src = readFileSync(file, 'utf8');
  if (!/^let wasmModule, wasmInstance, wasm;$/m.test(src) || !/\nfunction initSync\(module\) \{\n\s+if \(wasm !== undefined\) return wasm;/.test(src)) {
    throw new Error(`${file}: the wasm-bindgen glue changed shape; update scripts/patch-glue.mjs`);
  }
  // An error the module returns is thrown by the glue after the call; an exception
  // thrown through the module (page code run by a getter, unwinding wasm frames) is
  // not. Marking the first kind lets instance.js tell them apart.
  const returned = 'throw takeFromExternrefTable0(ret[1]);';
  if (!src.includes(returned)) throw new Error(`${file}: no '${returned}' in the glue; update scripts/patch-glue.mjs`);
  writeFileSync(file, `${src.replaceAll(returned, 'throw __wbg_returned(takeFromExternrefTable0(ret[1]));')}
/** Forgets the instance (after a trap), so that initSync makes a new one. */
export function __wbg_reset() {
    wasm = undefined;
    wasmInstance = undefined;
}

let __wbg_errorReturned = false;
function __wbg_returned(e) {
    __wbg_errorReturned = true;
    return e;
}
/** Whether the module returned an error since the last ask (and forgets it). */
export function __wbg_takeReturned() {
    const r = __wbg_errorReturned;
    __wbg_errorReturned = false;
    return r;
}
`);
}
