// patternsynth/texture: engines 2 and 3 only (texture synthesis, blends, seamless
// tiles) in their own wasm module. Images in and out are RGBA (an ImageData works);
// decode files with the browser (createImageBitmap) or patternsynth/codec.
import * as glue from './wasm/texture.js';
import { engine } from './instance.js';

const texture = engine(glue, new URL('./wasm/texture_bg.wasm', import.meta.url), 'patternsynth/texture');
const call = (name) => (...args) => texture.call(name, args);

export default texture.init;
export const initSync = texture.initSync;
/** How many times a trap (a bug) made the engine restart, for diagnostics. */
export const restarts = () => texture.restarts;

export const version = call('version');
export const synthesizeTexture = call('synthesizeTexture');
export const blendTextures = call('blendTextures');
export const seamlessTile = call('seamlessTile');
