// The package's entry points, declared once. The entry modules check their exports
// against it (tests), the worker dispatches by it and the client's methods are made
// from it. `args`: how many arguments the call takes before the progress callback;
// `progress`: whether it reports progress (and can be cancelled).
export const METHODS = {
  version: { args: 0 },
  parseSvg: { args: 2 },
  parseSvgReport: { args: 2 },
  classifyStrokes: { args: 2 },
  synthesizeStrokes: { args: 2, progress: true },
  strokeTile: { args: 2 },
  exampleStrokes: { args: 0 },
  synthesizeTexture: { args: 2, progress: true },
  blendTextures: { args: 3, progress: true },
  seamlessTile: { args: 2, progress: true },
  decodeImage: { args: 1 },
  encodePng: { args: 1 },
};
