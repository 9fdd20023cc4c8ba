// Whether this JavaScript engine runs wasm SIMD (simd128), which the texture engine's
// fast build needs: a module of one function that uses one SIMD instruction
// (i32.const 0; i8x16.splat) validates exactly where SIMD is supported. Every browser
// since 2023 (Safari 16.4) and Node 16.4 does; the rest load the scalar build, which
// gives the same images, 1.2-1.5 times slower.

const PROBE = new Uint8Array([
  0x00, 0x61, 0x73, 0x6d, 0x01, 0x00, 0x00, 0x00, // magic, version 1
  0x01, 0x05, 0x01, 0x60, 0x00, 0x01, 0x7b, // types: () -> v128
  0x03, 0x02, 0x01, 0x00, // one function of type 0
  0x0a, 0x08, 0x01, 0x06, 0x00, 0x41, 0x00, 0xfd, 0x0f, 0x0b, // its body
]);

/** Whether `wasm` (the WebAssembly namespace) validates a module that uses SIMD. */
export function supportsSimd(wasm = globalThis.WebAssembly) {
  try {
    return wasm.validate(PROBE);
  } catch {
    return false;
  }
}

/** Whether this engine runs SIMD, asked once. */
export const simd = supportsSimd();
