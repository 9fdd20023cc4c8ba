// Fill & mend tab: a photograph with a mask painted over it; fill the painted area,
// mend the photograph into a tile, or make more of it with the painted area kept out
// (and the material's other maps laid out the same way). Runs in the worker (progress,
// cancel); the photograph, the mask and the settings survive a reload.
import { actionHelp, actions, defaultOptions, imageKey, maskKey, maxInputSide, storageKey, textures } from '../shared/meta.js';
import { load, store } from '../../../shared/storage.js';
import { offerDownload, runControls, withdrawDownload } from '../../../shared/run.js';
import { maskPainter } from '../../../shared/mask.js';
import { fileBitmap, imagePicker } from '../../../shared/images.js';
import { keptResult } from '../../../shared/results.js';
import { sayInto } from '../../../shared/say.js';

export function mountRetouch(root, client) {
  const $ = (id) => root.querySelector(`#${id}`);
  const settings = { ...defaultOptions, ...load(storageKey, {}) };
  const save = () => store(storageKey, settings);
  const say = sayInto($('ret-messages'));
  let image = null;
  let maps = []; // [{ name, rgba }]: the material's other maps, at the photograph's size
  const urls = [];

  // --- the photograph and its mask ---
  const source = $('ret-source');
  const brush = $('ret-brush');
  brush.value = settings.brush;
  brush.addEventListener('input', () => { settings.brush = Number(brush.value); save(); });
  const erase = $('ret-erase');
  erase.checked = settings.erase === true;
  erase.addEventListener('change', () => { settings.erase = erase.checked; save(); });
  const mask = maskPainter({
    overlay: $('ret-mask'), brush, erase, clear: $('ret-clear'), key: maskKey,
    onChange: () => { $('ret-mask-info').textContent = mask.painted() ? 'painted' : 'nothing painted'; },
    onError: (e) => say(`The mask could not be kept (${e.message}): it lasts until this page closes.`, 'warn'),
  });
  function show(rgba) {
    source.width = rgba.width;
    source.height = rgba.height;
    source.getContext('2d').putImageData(new ImageData(new Uint8ClampedArray(rgba.data), rgba.width, rgba.height), 0, 0);
    mask.resize(rgba.width, rgba.height);
    image = rgba;
    maps = maps.filter((m) => m.rgba.width === rgba.width && m.rgba.height === rgba.height);
    showMaps();
    $('ret-source-info').textContent = `${rgba.width}×${rgba.height}`;
  }
  const picker = imagePicker({
    select: $('ret-texture'), file: $('ret-file'), drop: $('ret-drop'), textures, fallback: defaultOptions.texture,
    maxSide: maxInputSide, key: imageKey, settings, save, say, show, noun: 'photograph',
  });

  // --- the material's other maps ---
  function showMaps() {
    $('ret-maps-list').textContent = maps.length ? maps.map((m) => m.name).join(', ') : 'none';
  }
  $('ret-maps').addEventListener('change', async (e) => {
    const files = [...e.target.files];
    e.target.value = '';
    if (!image) return;
    const added = [];
    for (const file of files) {
      const bitmap = await fileBitmap(file);
      if (!bitmap) { say(`${file.name} is not an image this browser can read.`, 'error'); continue; }
      // A map is of its photograph's size: scaled to it (as the photograph was).
      const ctx = new OffscreenCanvas(image.width, image.height).getContext('2d');
      ctx.drawImage(bitmap, 0, 0, image.width, image.height);
      added.push({ name: file.name, rgba: { width: image.width, height: image.height, data: ctx.getImageData(0, 0, image.width, image.height).data } });
    }
    maps = [...maps, ...added];
    showMaps();
    if (added.length) say(`${added.length} map${added.length > 1 ? 's' : ''} added: each is laid out as the new texture is.`);
  });
  $('ret-maps-clear').addEventListener('click', () => { maps = []; showMaps(); });

  // --- settings ---
  const action = $('ret-action');
  action.append(...actions.map(([v, l]) => new Option(l, v)));
  for (const [id, key] of [['ret-action', 'action'], ['ret-band', 'band'], ['ret-seed', 'seed'], ['ret-width', 'width'], ['ret-height', 'height']]) {
    const el = $(id);
    el.value = settings[key];
    el.addEventListener('input', () => { settings[key] = el.value; save(); showAction(); });
  }
  function showAction() {
    $('ret-help').textContent = actionHelp[settings.action] ?? '';
    $('ret-band-row').hidden = settings.action !== 'mend';
    $('ret-size-row').hidden = settings.action !== 'more';
    $('ret-maps-row').hidden = settings.action !== 'more';
    $('ret-band-out').value = `${Math.round(100 * Number(settings.band))}%`;
    $('ret-run').textContent = { fill: 'Fill', mend: 'Make tile', more: 'Make texture' }[settings.action] ?? 'Run';
  }

  // --- results ---
  /** `rgba` as a PNG Blob. */
  async function png(rgba, canvas = document.createElement('canvas')) {
    canvas.width = rgba.width;
    canvas.height = rgba.height;
    canvas.getContext('2d').putImageData(new ImageData(new Uint8ClampedArray(rgba.data), rgba.width, rgba.height), 0, 0);
    return new Promise((ok) => canvas.toBlob(ok, 'image/png'));
  }
  const urlOf = (blob) => {
    const url = URL.createObjectURL(blob);
    urls.push(url);
    return url;
  };
  /** Offers the result `{ blob, file, info, maps: [{ name, blob, file }] }` (shown
   *  already) and its maps for download. */
  function offer({ blob, file, info, maps: made = [] }) {
    offerDownload($('ret-download'), urlOf(blob));
    $('ret-download').download = file;
    $('ret-map-downloads').replaceChildren(...made.map((m) => Object.assign(document.createElement('a'), {
      className: 'button', textContent: `Download ${m.name}`, href: urlOf(m.blob), download: m.file,
    })));
    $('ret-info').textContent = info;
  }
  function clearResults() {
    for (const u of urls.splice(0)) URL.revokeObjectURL(u);
    withdrawDownload($('ret-download'));
    $('ret-map-downloads').replaceChildren();
    $('ret-view').classList.remove('shown');
  }
  /** Shows `rgba`, repeated 2 x 2 when it is a tile. */
  function showResult(rgba, repeat) {
    const c = $('ret-result');
    const k = repeat ? 2 : 1;
    c.width = k * rgba.width;
    c.height = k * rgba.height;
    const tile = new ImageData(new Uint8ClampedArray(rgba.data), rgba.width, rgba.height);
    const ctx = c.getContext('2d');
    for (let y = 0; y < k; y++) for (let x = 0; x < k; x++) ctx.putImageData(tile, x * rgba.width, y * rgba.height);
    c.setAttribute('aria-label', repeat ? 'The tile repeated 2 × 2: its wrap crosses the middle' : 'The result');
    $('ret-view').classList.add('shown');
  }

  // --- run ---
  const runs = runControls({ run: $('ret-run'), cancel: $('ret-cancel'), progress: $('ret-progress'), say });
  $('ret-run').addEventListener('click', async () => {
    if (!image) return say('Load a photograph first.', 'error');
    const painted = mask.painted();
    const seed = Number(settings.seed) || 0;
    if (settings.action === 'fill' && !painted) return say('Paint over what should go first (or pick another action).', 'error');
    clearResults();
    const t0 = performance.now();
    const kind = settings.action;
    $('ret-info').textContent = 'Working…';
    await runs.start({ fill: 'Filling…', mend: 'Making the tile…', more: 'Making the texture…' }[kind], async (call) => {
      let out, note = '', laidOut = [];
      if (kind === 'fill') {
        out = await client.inpaintTexture(image, mask.image(), { seed }, call);
      } else if (kind === 'mend') {
        const r = await client.seamlessTile(image, { method: 'mend', band: Number(settings.band), seed, sampleMask: painted ? mask.image() : undefined }, call);
        out = r.image;
        note = `, seam score ${r.seamScore.toFixed(2)} (about 1: no seam)`;
      } else {
        const width = Number(settings.width), height = Number(settings.height);
        const opts = { width, height, seed, sampleMask: painted ? mask.image() : undefined, keepLayout: maps.length > 0 };
        const r = await client.synthesizeTexture(image, opts, call);
        out = maps.length ? r.image : r;
        if (maps.length) {
          const replayed = await client.applyLayout(r.layout, maps.map((m) => m.rgba), { signal: call.signal });
          laidOut = await Promise.all(replayed.map(async (img, i) => ({
            name: maps[i].name, blob: await png(img), file: `${maps[i].name.replace(/\.[^.]+$/, '')}-${width}x${height}.png`,
          })));
          note = `, ${maps.length} map${maps.length > 1 ? 's' : ''} laid out the same way`;
        }
      }
      const ms = performance.now() - t0;
      showResult(out, kind === 'mend');
      const made = { blob: await png(out, $('ret-canvas')), file: `${kind}-${out.width}x${out.height}.png`, info: `${out.width}×${out.height}${note}, ${ms.toFixed(0)} ms`, repeat: kind === 'mend', maps: laidOut };
      offer(made);
      result.keep(made);
      say('Done.');
    });
    if (!$('ret-view').classList.contains('shown')) $('ret-info').textContent = `No result: see the message under ${$('ret-run').textContent}.`;
  });

  // --- the result, kept across reloads (shared/results.js) ---
  const result = keptResult('retouch', {
    links: [$('ret-download')],
    onError: (e) => say(`This browser would not keep the result (${e?.message ?? e}): download it to keep it.`, 'warn'),
  });
  result.restore().then(async (kept) => {
    if (!kept?.blob || runs.busy || urls.length) return;
    const bitmap = await createImageBitmap(kept.blob).catch(() => null);
    if (!bitmap || runs.busy || urls.length) return;
    const ctx = new OffscreenCanvas(bitmap.width, bitmap.height).getContext('2d');
    ctx.drawImage(bitmap, 0, 0);
    showResult({ width: bitmap.width, height: bitmap.height, data: ctx.getImageData(0, 0, bitmap.width, bitmap.height).data }, kept.repeat);
    offer(kept);
  });

  // --- start ---
  showAction();
  showMaps();
  // The photograph first, then its mask over it.
  picker.start().then(() => mask.restore());
}
