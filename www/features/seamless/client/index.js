// Seamless tile tab: pick or drop an image, choose the method, make a tile in the
// worker (progress, cancel), judge it repeated 3x3, download PNG.
import { defaultOptions, imageKey, maxInputSide, methodHelp, methods, storageKey, textures } from '../shared/meta.js';
import { load, store } from '../../../shared/storage.js';
import { runControls } from '../../../shared/run.js';
import { zoomable } from '../../../shared/zoom.js';
import { tilePanel } from '../../../shared/tile.js';
import { imagePicker } from '../../../shared/images.js';
import { keptResult } from '../../../shared/results.js';
import { sayInto } from '../../../shared/say.js';

export function mountSeamless(root, client) {
  const $ = (id) => root.querySelector(`#${id}`);
  const settings = { ...defaultOptions, ...load(storageKey, {}) };
  const save = () => store(storageKey, settings);
  const say = sayInto($('seam-messages'));
  let image = null;
  let resultUrl = null;
  let shownScale = 1; // the tile's screen pixels per pixel in its repeat (see `tilePanel.show`)

  // --- the exemplar ---
  function show(rgba) {
    const c = $('seam-source');
    c.width = rgba.width;
    c.height = rgba.height;
    c.getContext('2d').putImageData(new ImageData(new Uint8ClampedArray(rgba.data), rgba.width, rgba.height), 0, 0);
    image = rgba;
    $('seam-source-info').textContent = `${rgba.width}×${rgba.height}`;
  }
  const picker = imagePicker({
    select: $('seam-texture'), file: $('seam-file'), drop: $('seam-drop'), textures,
    fallback: defaultOptions.texture, maxSide: maxInputSide, key: imageKey, settings, save, say, show, noun: 'texture',
  });

  // --- settings ---
  const method = $('seam-method');
  method.append(...methods.map(([v, l]) => new Option(l, v)));
  for (const [id, key] of [['seam-method', 'method'], ['seam-size', 'size'], ['seam-seed', 'seed'], ['seam-t0', 'maxCountDifference'], ['seam-width', 'width'], ['seam-height', 'height']]) {
    const el = $(id);
    el.value = settings[key];
    el.addEventListener('input', () => { settings[key] = el.value; save(); showMethod(); });
  }
  const refine = $('seam-refine');
  refine.checked = settings.refine !== false;
  refine.addEventListener('change', () => { settings.refine = refine.checked; save(); });
  const showMethod = () => {
    $('seam-t0-row').hidden = settings.method === 'synthesis';
    $('seam-refine-row').hidden = settings.method === 'synthesis';
    $('seam-custom').hidden = settings.size !== 'custom';
    $('seam-method-help').textContent = methodHelp[settings.method] ?? '';
  };
  const tile = tilePanel({ preview: $('seam-repeat'), download: $('seam-download'), css: $('seam-css'), copy: $('seam-copy'), offset: $('seam-offset') });

  // The tile repeated zooms (pixels shown as they are) and pans, to look at its seams.
  const zoom = zoomable($('seam-view'), {
    zoomIn: $('seam-zoom-in'), zoomOut: $('seam-zoom-out'), fit: $('seam-zoom-fit'), actual: $('seam-zoom-actual'), level: $('seam-zoom-level'),
    shown: () => $('seam-repeat').classList.contains('shown'),
    // (The tile is drawn as a background at the scale it was shown at, whatever
    // width its repeat's box is given.)
    scale: () => shownScale,
  });

  // --- run ---
  const runs = runControls({ run: $('seam-run'), cancel: $('seam-cancel'), progress: $('seam-progress'), say });
  $('seam-run').addEventListener('click', async () => {
    if (!image) return say('Load an image first.', 'error');
    const opts = { method: settings.method, seed: Number(settings.seed) || 0 };
    if (settings.size === 'custom') {
      // Any size is toroidal synthesis's: E-TFMCM's fractal makes square powers of two.
      if (settings.method !== 'synthesis') return say('Tiles of any width and height are made by toroidal synthesis: choose it as the method, or a power-of-two size.', 'error');
      [opts.width, opts.height] = [Number(settings.width), Number(settings.height)];
    } else if (settings.size) opts.size = Number(settings.size);
    if (settings.method !== 'synthesis') {
      opts.maxCountDifference = Number(settings.maxCountDifference);
      opts.refine = settings.refine !== false;
    }
    const t0 = performance.now();
    // The previous tile goes: should this run fail, it must not look like its result.
    tile.clear();
    $('seam-info').textContent = 'Making the tile…';
    await runs.start('Making the tile…', async (call) => {
      const r = await client.seamlessTile(image, opts, call);
      const ms = performance.now() - t0;
      const { width, height } = r.image;
      const c = $('seam-result');
      c.width = width;
      c.height = height;
      c.getContext('2d').putImageData(new ImageData(new Uint8ClampedArray(r.image.data), width, height), 0, 0);
      const blob = await new Promise((ok) => c.toBlob(ok, 'image/png'));
      const made = {
        blob, width, height, file: `seamless-${settings.method}-${width}x${height}.png`,
        info: `${width}×${height}, restoration rate ${(100 * r.restorationRate).toFixed(1)}%, seam score ${r.seamScore.toFixed(2)} (about 1: no seam), ${ms.toFixed(0)} ms`,
      };
      showTile(made);
      result.keep(made);
      say(r.warnings.length ? r.warnings.join(' ') : 'Done.', r.warnings.length ? 'warn' : '');
    });
    if (!$('seam-repeat').classList.contains('shown')) $('seam-info').textContent = 'No tile: see the message under Make tile.';
  });

  // --- the tile, kept across reloads (shared/results.js) ---
  const result = keptResult('seamless', {
    links: [$('seam-download')],
    onError: (e) => say(`This browser would not keep the tile (${e?.message ?? e}): download it to keep it.`, 'warn'),
  });
  /** Shows the tile (a PNG `blob`) repeated 3 x 3, to judge the seams, and offers it. */
  function showTile({ blob, width, height, file, info }) {
    if (resultUrl) URL.revokeObjectURL(resultUrl);
    resultUrl = URL.createObjectURL(blob);
    // Whole pixels when the column has room, scaled down to fit it when it has not.
    // (A tab not shown has no width: the page's, less its margins, stands in.)
    const room = $('seam-view').parentElement.clientWidth || document.documentElement.clientWidth - 34;
    const fit = Math.min(512, room - 16) / (3 * width);
    const scale = fit >= 1 ? Math.floor(fit) : fit;
    shownScale = scale;
    tile.show({ url: resultUrl, file, width, height, scale });
    zoom.reset(); // (after the tile is shown: it enables the zoom)
    $('seam-info').textContent = info;
  }
  result.restore().then((kept) => {
    if (kept?.blob && !runs.busy && !resultUrl) showTile(kept);
  });

  // --- start ---
  showMethod();
  picker.start();
}
