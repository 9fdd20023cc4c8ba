// patternsynth: the vector and texture engines in one module (see patternsynth.js);
// the codecs load separately (initCodecs).
import type { Init, InitSync } from './types.js';
export type * from './types.js';

declare const init: Init;
export default init;
export declare const initSync: InitSync;
/** How many times a trap (a bug) made the engine restart. */
export function restarts(): number;
/** Loads the image codec module (decodeImage, encodePng); Node loads it at import. */
export declare const initCodecs: Init;
export declare const initCodecsSync: InitSync;
export { version, parseSvg, parseSvgReport, classifyStrokes, synthesizeStrokes, strokeTile, suggestStrokes } from './vector.js';
export { synthesizeTexture, blendTextures, seamlessTile } from './texture.js';
export { decodeImage, encodePng } from './codec.js';
