// patternsynth/vector: engine 1 only (strokes, SVG import and export, tiles) in its own
// wasm module, for pages that make vector patterns. `await init()` once, then call.
import * as glue from './wasm/vector.js';
import { engine } from './instance.js';

const vector = engine(glue, new URL('./wasm/vector_bg.wasm', import.meta.url), 'patternsynth/vector');
const call = (name) => (...args) => vector.call(name, args);

export default vector.init;
export const initSync = vector.initSync;
/** How many times a trap (a bug) made the engine restart, for diagnostics. */
export const restarts = () => vector.restarts;

export const version = call('version');
export const parseSvg = call('parseSvg');
export const parseSvgReport = call('parseSvgReport');
export const classifyStrokes = call('classifyStrokes');
export const synthesizeStrokes = call('synthesizeStrokes');
export const strokeTile = call('strokeTile');
export const exampleStrokes = call('exampleStrokes');
