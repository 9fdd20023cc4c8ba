// CommonJS TypeScript (module node16): `import` compiles to `require`.
import { synthesizeStrokes, version, type Stroke } from 'patternsynth';
import { strokeTile } from 'patternsynth/vector';
const strokes: Stroke[] = [{ points: [[0, 0], [4, 4]], width: 1 }, { points: [[20, 0], [24, 4]], width: 1 }];
console.log(version(), synthesizeStrokes(strokes, { width: 60, height: 10 }).strokes.length, typeof strokeTile);
