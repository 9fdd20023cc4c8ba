// A TypeScript site's use of the package, checked with tsc --strict.
import init, { synthesizeStrokes, parseSvg, decodeImage, encodePng, initCodecs, type Stroke, type Progress } from 'patternsynth';
import initVector, { strokeTile, type TileResult } from 'patternsynth/vector';
import initTexture, { seamlessTile, type SeamlessResult } from 'patternsynth/texture';
import initCodec, { decodeImage as decode } from 'patternsynth/codec';
import { PatternSynthClient } from 'patternsynth/client';

await init();
await initCodecs();
await Promise.all([initVector(new URL('x.wasm', import.meta.url)), initTexture(), initCodec()]);
const repeat: TileResult = strokeTile([], { repeats: 2 });
const seamless: SeamlessResult = seamlessTile(decode(new Uint8Array(8)), { method: 'synthesis' });
const strokes: Stroke[] = parseSvg('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 9 9"/>');
const onProgress: Progress = (f) => { console.log(f); };
const result = synthesizeStrokes(strokes, { width: 100, height: 100 }, onProgress);
const count: number = result.strokes.length + synthesizeStrokes(strokes, { width: 10, height: 10 }).classes.length;
const client = new PatternSynthClient();
const texture = await client.synthesizeTexture({ width: 1, height: 1, data: new Uint8Array(4) }, { width: 8, height: 8 }, { onProgress: (f) => console.log(f) });
const shown = new ImageData(texture.data, texture.width, texture.height);
const png: Uint8Array = encodePng(decodeImage(new Uint8Array(8)));
const tile = await client.seamlessTile(texture);
new ImageData(tile.image.data, tile.image.width, tile.image.height);
const worker = new PatternSynthClient(() => new Worker(new URL('patternsynth/worker', import.meta.url), { type: 'module' }));
// The types refuse what the runtime refuses:
// @ts-expect-error the output size is required
synthesizeStrokes(strokes, {});
// @ts-expect-error images are { width, height, data }
client.synthesizeTexture(new Uint8Array(4), { width: 8, height: 8 });
// @ts-expect-error the vector entry has no texture engine
import('patternsynth/vector').then((m) => m.synthesizeTexture);
export { count, shown, png, worker, repeat, seamless };
