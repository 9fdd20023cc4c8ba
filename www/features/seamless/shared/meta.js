// Seamless tile: label, options and defaults (shared by the page and tests).
export const label = 'Seamless tile';

export const defaultOptions = {
  // Toroidal synthesis by measurement (issue 25): on 12 photographs from Debian's game and
  // GIMP packages it had lower patch energy than refined E-TFMCM (0.88 against 0.91 of
  // texture-synthesis's, mean over seeds 1-3) and every seam within 0.8-1.2 (10 of 12).
  method: 'synthesis', // 'etfmcm' | 'tfmcm'
  size: '', // '' = the image's own size (E-TFMCM: the largest power of two it allows); 'custom' = width x height
  width: 300, // a custom tile's (toroidal synthesis only)
  height: 200,
  seed: 1,
  maxCountDifference: 50,
  // E-TFMCM and TFMCM: their tile refined by toroidal synthesis (bench: examples/tile_quality).
  refine: true,
  texture: 'gravel',
};

export const methods = [
  ['synthesis', 'Toroidal synthesis (keeps structure)'],
  ['etfmcm', 'E-TFMCM (the paper: co-occurrence fractal)'],
  ['tfmcm', 'TFMCM (its predecessor, for comparison)'],
];

/** What each method does, in plain words. */
export const methodHelp = {
  etfmcm: 'Rebuilds the tile from how the image\'s colours sit next to one another, so the tile keeps the image\'s colours in their proportions; refined, its detail is then re-made from the image, otherwise shapes larger than a few pixels break up.',
  tfmcm: 'The same idea without the fractal refinement: faster, rougher. For comparison.',
  synthesis: 'Grows the tile pixel by pixel from the image\'s own neighbourhoods, wrapping round its edges: keeps structure (bricks, weave, wood grain). A photograph of a few large pieces (big stone blocks, wide planks) breaks up: \u201cMake it tile\u201d in Fill & mend keeps them whole.',
};

/** Built-in photographs (CC0, public domain or unrestricted; see tests/fixtures/textures/SOURCES.md). */
export const textures = ['wood', 'brick', 'grass', 'gravel', 'fur', 'hubble', 'tissue', 'coins'];

/** Images larger than this are scaled down before they reach the engine. */
export const maxInputSide = 1024;

export const storageKey = 'patternsynth.seamless.settings.v1';
export const imageKey = 'patternsynth.seamless.image.v1';
