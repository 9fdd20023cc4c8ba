// The package's entry points, declared once. The entry modules check their exports
// against it (tests), the worker dispatches by it and the client's methods are made
// from it. `args`: how many arguments the call takes before the progress callback;
// `progress`: whether it reports progress (and can be cancelled); `module`: the wasm
// module that has it (`version` is in every one); `strokes`: its first argument is
// strokes (their points are flattened before they cross: flat.js). The main entry has `vector` and
// `texture` in one module and loads `codec` on demand.
export const METHODS = {
  version: { args: 0 },
  parseSvg: { args: 2, module: 'vector' },
  parseSvgReport: { args: 2, module: 'vector' },
  classifyStrokes: { args: 2, strokes: true, module: 'vector' },
  synthesizeStrokes: { args: 2, strokes: true, progress: true, module: 'vector' },
  strokeTile: { args: 2, strokes: true, module: 'vector' },
  suggestStrokes: { args: 2, strokes: true, module: 'vector' },
  synthesizeTexture: { args: 2, progress: true, module: 'texture' },
  blendTextures: { args: 3, progress: true, module: 'texture' },
  seamlessTile: { args: 2, progress: true, module: 'texture' },
  inpaintTexture: { args: 3, progress: true, module: 'texture' },
  transferStyle: { args: 3, progress: true, module: 'texture' },
  applyLayout: { args: 2, module: 'texture' },
  decodeImage: { args: 1, module: 'codec' },
  encodePng: { args: 1, module: 'codec' },
};

// The wasm exports of banded synthesis, which workers call for the client (bands.js);
// the entries with the texture engine carry them as `bands`, not as API.
export const BAND_EXPORTS = ['bandsOpen', 'bandsRun', 'bandsClose', 'bandsOpenJobs'];
