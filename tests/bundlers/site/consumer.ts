// A TypeScript site's use of the package, checked with tsc --strict.
import init, { synthesizeStrokes, parseSvg, decodeImage, encodePng, type Stroke, type Progress } from 'patternsynth';
import { PatternSynthClient } from 'patternsynth/client';

await init();
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
export { count, shown, png, worker };
