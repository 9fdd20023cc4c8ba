// The package's main entry: the vector and texture engines in one wasm module. `await
// init()` once (or `initSync({ module })`), then call the functions; see README.md.
// The image codecs are a separate module: `await initCodecs()` before decodeImage or
// encodePng in a browser (Node loads them at import).
import * as glue from './wasm/full.js';
import { engine } from './instance.js';

const full = engine(glue, new URL('./wasm/full_bg.wasm', import.meta.url), 'patternsynth');
const call = (name) => (...args) => full.call(name, args);

export default full.init;
export const initSync = full.initSync;
/** How many times a trap (a bug) made the engine restart, for diagnostics. */
export const restarts = () => full.restarts;
export { default as initCodecs, initSync as initCodecsSync, decodeImage, encodePng } from './codec.js';

export const version = call('version');
export const parseSvg = call('parseSvg');
export const parseSvgReport = call('parseSvgReport');
export const classifyStrokes = call('classifyStrokes');
export const synthesizeStrokes = call('synthesizeStrokes');
export const strokeTile = call('strokeTile');
export const exampleStrokes = call('exampleStrokes');
export const synthesizeTexture = call('synthesizeTexture');
export const blendTextures = call('blendTextures');
export const seamlessTile = call('seamlessTile');
