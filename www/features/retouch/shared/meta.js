// Fill & mend: label, options and defaults (shared by the page and tests).
export const label = 'Fill & mend';

export const defaultOptions = {
  // 'fill': the painted pixels re-made from the rest of the photograph (inpaintTexture);
  // 'mend': the photograph made to tile, only a band around its wrap re-made, the
  // painted pixels never copied into it (seamlessTile method 'mend');
  // 'more': more of the photograph at any size, the painted pixels never copied, and
  // the material's other maps laid out the same way (synthesizeTexture + applyLayout).
  action: 'fill',
  // The mend's band (whole width as a share of each side): 0.25 put 9 of the 10 fixture
  // photographs' wraps in 0.8-1.2 (0.125: 8, 0.375: 8; examples/seam_profile mend).
  band: 0.25,
  width: 512,
  height: 512,
  seed: 1,
  brush: 24,
  erase: false, // the brush erases the mask
  texture: 'brick',
};

export const actions = [
  ['fill', 'Fill the painted area'],
  ['mend', 'Make it tile (re-make the edges)'],
  ['more', 'Make more of it (painted area kept out)'],
];

/** What each action does, in plain words. */
export const actionHelp = {
  fill: 'Paint over what should go (a pipe, a logo, a blemish): it is re-made from the rest of the photograph. Every pixel you did not paint stays exactly as it was.',
  mend: 'Keeps the photograph as it is and re-makes only a band along its edges, so that it repeats without a seam. Painted pixels are never copied into the band.',
  more: 'Makes a new texture of any size from the photograph, never copying the painted pixels. Add the material\'s other maps (normal, roughness, height) to get each laid out the same way.',
};

/** Built-in photographs (see tests/fixtures/textures/SOURCES.md). */
export const textures = ['brick', 'wood', 'grass', 'gravel', 'fur', 'tissue', 'coins'];

/** Photographs larger than this are scaled down before they reach the engine. */
export const maxInputSide = 1024;

export const storageKey = 'patternsynth.retouch.settings.v1';
export const imageKey = 'patternsynth.retouch.image.v1';
export const maskKey = 'patternsynth.retouch.mask.v1';
