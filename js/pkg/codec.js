// patternsynth/codec: PNG and JPEG decoding and PNG encoding in wasm, its own module.
// Node needs it (the Node entries load it at import); a browser decodes natively
// (createImageBitmap, canvas.toBlob) and need not load it at all.
import * as glue from './wasm/codec.js';
import { engine } from './instance.js';

const codec = engine(
  glue,
  new URL('./wasm/codec_bg.wasm', import.meta.url),
  'patternsynth',
  '`await initCodecs()` first (or `await init()` from patternsynth/codec); in a browser, createImageBitmap decodes natively',
);

export default codec.init;
export const initSync = codec.initSync;
/** How many times the engine replaced its instance after a trap (a bug) or an exception
 *  thrown through it, for diagnostics. */
export const restarts = () => codec.restarts;
/** The engine's restarts, renewals (instances replaced to give memory back) and memory. */
export const diagnostics = () => codec.diagnostics();

export const version = codec.method('version');
export const decodeImage = codec.method('decodeImage');
export const encodePng = codec.method('encodePng');
