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
/** How many times a trap (a bug) made the engine restart, for diagnostics. */
export const restarts = () => codec.restarts;

export const version = codec.method('version');
export const decodeImage = codec.method('decodeImage');
export const encodePng = codec.method('encodePng');
