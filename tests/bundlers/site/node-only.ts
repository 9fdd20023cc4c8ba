// Node-only TypeScript (no DOM library): the package's types must not need it.
import { synthesizeStrokes, initSync, type Stroke } from 'patternsynth';
import { readFileSync } from 'node:fs';
initSync({ module: readFileSync(new URL('x.wasm', import.meta.url)) });
const strokes: Stroke[] = [{ points: [[0, 0], [1, 1]], width: 1 }];
const n: number = synthesizeStrokes(strokes, { width: 10, height: 10 }).strokes.length;
console.log(n);
