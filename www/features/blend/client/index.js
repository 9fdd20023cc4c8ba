// Blend tab: two exemplars (built-in photographs, files, drag and drop), a transition or
// a painted mask, synthesis in the worker with progress and cancel, PNG download.
import { defaultOptions, exemplarKey, maskKey, maxExemplarSide, maxOutputSide, storageKey, textures } from '../shared/meta.js';
import { load, store } from '../../../shared/storage.js';
import { offerDownload, runControls } from '../../../shared/run.js';
import { zoomable } from '../../../shared/zoom.js';
import { keptResult } from '../../../shared/results.js';
import { keyboardBrush } from '../../../shared/mask.js';
import { imagePicker } from '../../../shared/images.js';
import { sayInto } from '../../../shared/say.js';

/** The coefficient transfers, as the engine defines them (mu of A in [0, 1]). */
const TRANSFER = {
  linear: (t) => t,
  ease: (t) => 0.5 + 4 * (t - 0.5) ** 3,
  steep: (t) => {
    const s = (u) => 1 / (1 + Math.exp(-14 * (u - 0.5)));
    return (s(t) - s(0)) / (s(1) - s(0));
  },
};

/** mu at (x, y) of a w x h image for a shape, as the engine computes it. */
function coefficientAt(shape, angle, w, h) {
  if (shape === 'radial') {
    const cx = (w - 1) / 2, cy = (h - 1) / 2, r = Math.hypot(cx, cy) || 1;
    return (x, y) => 1 - Math.hypot(x - cx, y - cy) / r;
  }
  const a = (angle * Math.PI) / 180, dx = Math.cos(a), dy = Math.sin(a);
  const proj = (x, y) => x * dx + y * dy;
  const c = [proj(0, 0), proj(w - 1, 0), proj(0, h - 1), proj(w - 1, h - 1)];
  const lo = Math.min(...c), span = Math.max(Math.max(...c) - lo, 1e-9);
  const f = TRANSFER[shape] ?? TRANSFER.linear;
  return (x, y) => f(Math.min(1, Math.max(0, 1 - (proj(x, y) - lo) / span)));
}

/**
 * A note for outputs many times an exemplar's area: each of its features must then recur
 * about that many times (a 128 px grass at 1024 px must show each clump about 64 times;
 * texture-synthesis's output of it repeats its clumps alike), which only a larger
 * exemplar avoids.
 */
function recurrence(out, exemplars) {
  const times = (out.width * out.height) / Math.min(...exemplars.map((e) => e.width * e.height));
  if (times < 16) return '';
  return `. The output is ${Math.round(times)} times the exemplar's area, so each of its features recurs about as often; a larger exemplar repeats less.`;
}

export function mountBlend(root, client) {
  const $ = (id) => root.querySelector(`#${id}`);
  const settings = { ...defaultOptions, ...load(storageKey, {}) };
  const save = () => store(storageKey, settings);
  const say = sayInto($('blend-messages'));
  let resultUrl = null;

  // --- exemplar slots: one picture input each (`imagePicker`), texture A and B ---
  const slots = {};
  function setSlot(key, rgba) {
    const { canvas } = slots[key];
    canvas.width = rgba.width;
    canvas.height = rgba.height;
    canvas.getContext('2d').putImageData(new ImageData(new Uint8ClampedArray(rgba.data), rgba.width, rgba.height), 0, 0);
    slots[key].image = rgba;
  }
  for (const [key, fallback] of [['a', 'wood'], ['b', 'gravel']]) {
    const fig = root.querySelector(`[data-slot="${key}"]`);
    slots[key] = { fig, canvas: fig.querySelector('canvas'), image: null };
    slots[key].picker = imagePicker({
      select: fig.querySelector('select'), file: fig.querySelector('input[type=file]'), drop: fig, textures, fallback,
      maxSide: maxExemplarSide, key: `${exemplarKey}.${key}`, settings, setting: key, save, say,
      show: (rgba) => setSlot(key, rgba), noun: 'texture', as: `texture ${key.toUpperCase()}`,
    });
  }

  // --- settings ---
  const modeInputs = root.querySelectorAll('input[name="blend-mode"]');
  for (const r of modeInputs) {
    r.checked = r.value === settings.mode;
    r.addEventListener('change', () => { settings.mode = r.value; save(); showMode(); });
  }
  const showMode = () => {
    const single = settings.mode === 'single';
    $('transition-set').disabled = single;
    slots.b.fig.style.opacity = single ? 0.4 : 1;
  };
  const bindValue = (id, key, parse = (v) => v) => {
    const el = $(id);
    el.value = settings[key];
    el.addEventListener('input', () => { settings[key] = parse(el.value); save(); });
    return el;
  };
  const bindCheck = (id, key) => {
    const el = $(id);
    el.checked = settings[key];
    el.addEventListener('change', () => { settings[key] = el.checked; save(); });
  };
  bindValue('blend-width', 'width', Number);
  bindValue('blend-height', 'height', Number);
  bindValue('blend-neighbourhood', 'neighbourhood', Number);
  bindValue('blend-levels', 'levels');
  bindValue('blend-seed', 'seed', Number);
  bindCheck('blend-tileable', 'tileable');
  bindCheck('blend-exhaustive', 'exhaustive');
  const transition = bindValue('blend-transition', 'transition');
  const angle = bindValue('blend-angle', 'angle', Number);
  const showAngle = () => { $('blend-angle-out').value = `${settings.angle}°`; };
  angle.addEventListener('input', () => { showAngle(); drawShape(); });
  transition.addEventListener('change', () => drawShape());

  // --- the coefficient preview and painted mask ---
  const mask = $('blend-mask');
  const mctx = mask.getContext('2d', { willReadFrequently: true });
  function drawShape() {
    if (settings.transition === 'mask') return;
    const mu = coefficientAt(settings.transition, settings.angle, mask.width, mask.height);
    const img = mctx.createImageData(mask.width, mask.height);
    for (let y = 0; y < mask.height; y++) for (let x = 0; x < mask.width; x++) {
      const v = Math.round(255 * mu(x, y)), i = 4 * (y * mask.width + x);
      img.data[i] = img.data[i + 1] = img.data[i + 2] = v;
      img.data[i + 3] = 255;
    }
    mctx.putImageData(img, 0, 0);
  }
  $('mask-reset').addEventListener('click', () => {
    if (settings.transition === 'mask') {
      settings.transition = 'linear';
      transition.value = 'linear';
    }
    drawShape();
    save();
  });
  // The brush: its size and what it paints, kept with the settings.
  const brushSize = bindValue('brush-size', 'brushSize', Number);
  for (const r of root.querySelectorAll('input[name="brush"]')) {
    r.checked = r.value === settings.brush;
    r.addEventListener('change', () => { settings.brush = r.value; save(); });
  }
  /** A soft dab at (x, y) in mask pixels, of A (white) or B (black); the transition
   *  becomes the painted mask. */
  const dab = (x, y) => {
    if (settings.transition !== 'mask') {
      settings.transition = 'mask';
      transition.value = 'mask';
    }
    const size = Number(brushSize.value);
    const g = mctx.createRadialGradient(x, y, 0, x, y, size / 2);
    const c = settings.brush === 'b' ? '0,0,0' : '255,255,255';
    g.addColorStop(0, `rgba(${c},0.6)`);
    g.addColorStop(1, `rgba(${c},0)`);
    mctx.fillStyle = g;
    mctx.beginPath();
    mctx.arc(x, y, size / 2, 0, Math.PI * 2);
    mctx.fill();
  };
  const keepMask = () => {
    // Its grey levels, read now and written at once (a PNG from toBlob came a second
    // later, and a reload within it lost the mask 5 times in 5).
    const { data } = mctx.getImageData(0, 0, mask.width, mask.height);
    const grey = new Uint8Array(mask.width * mask.height);
    for (let i = 0; i < grey.length; i++) grey[i] = data[4 * i];
    store(maskKey, { width: mask.width, height: mask.height, grey });
    save();
  };
  let painting = false;
  const paint = (e) => {
    const r = mask.getBoundingClientRect();
    dab(((e.clientX - r.left) * mask.width) / r.width, ((e.clientY - r.top) * mask.height) / r.height);
  };
  mask.addEventListener('pointerdown', (e) => {
    painting = true;
    mask.setPointerCapture(e.pointerId);
    paint(e);
  });
  mask.addEventListener('pointermove', (e) => { if (painting) paint(e); });
  const endPaint = () => {
    if (!painting) return;
    painting = false;
    keepMask();
  };
  mask.addEventListener('pointerup', endPaint);
  mask.addEventListener('pointercancel', endPaint);
  // From the keyboard as the fill's mask is painted (shared/mask.js).
  keyboardBrush({ canvas: mask, brush: brushSize, dab, done: keepMask });

  /** The painted mask resampled to the output size, as mu values. */
  function maskCoefficient(w, h) {
    const c = new OffscreenCanvas(w, h);
    const ctx = c.getContext('2d');
    ctx.drawImage(mask, 0, 0, w, h);
    const d = ctx.getImageData(0, 0, w, h).data;
    const mu = new Float32Array(w * h);
    for (let i = 0; i < mu.length; i++) mu[i] = d[4 * i] / 255;
    return mu;
  }

  // --- run ---
  const runs = runControls({ run: $('blend-run'), cancel: $('blend-cancel'), progress: $('blend-progress'), say });
  $('blend-run').addEventListener('click', async () => {
    const width = Number(settings.width), height = Number(settings.height);
    if (!(width >= 8 && height >= 8 && width <= maxOutputSide && height <= maxOutputSide)) {
      return say(`Output width and height must be between 8 and ${maxOutputSide}.`, 'error');
    }
    const single = settings.mode === 'single';
    if (!slots.a.image || (!single && !slots.b.image)) return say('Load both textures first.', 'error');
    const base = { width, height, seed: Number(settings.seed) || 0, tileable: settings.tileable, exhaustive: settings.exhaustive, neighbourhood: Number(settings.neighbourhood) };
    if (settings.levels) base.levels = Number(settings.levels);
    const t0 = performance.now();
    await runs.start('Synthesizing…', async (call) => {
      let out;
      if (single) out = await client.synthesizeTexture(slots.a.image, base, call);
      else {
        const t = settings.transition;
        const opts = { ...base };
        if (t === 'mask') opts.coefficient = maskCoefficient(width, height);
        else if (t === 'radial') opts.coefficient = 'radial';
        else {
          opts.coefficient = t;
          if (settings.angle !== 90) opts.angle = settings.angle;
        }
        out = await client.blendTextures(slots.a.image, slots.b.image, opts, call);
      }
      const ms = performance.now() - t0;
      const canvas = $('blend-result');
      canvas.width = out.width;
      canvas.height = out.height;
      canvas.getContext('2d').putImageData(new ImageData(new Uint8ClampedArray(out.data), out.width, out.height), 0, 0);
      const blob = await new Promise((ok) => canvas.toBlob(ok, 'image/png'));
      const file = `${single ? 'texture' : 'blend'}-${out.width}x${out.height}.png`;
      const info = `${out.width}×${out.height}, ${single ? 'single exemplar' : settings.transition}, ${ms.toFixed(0)} ms${recurrence(out, single ? [slots.a.image] : [slots.a.image, slots.b.image])}`;
      offerResult({ blob, file, info });
      result.keep({ blob, file, info });
      say('Done.');
    });
  });

  // --- the result, kept across reloads (shared/results.js) ---
  const result = keptResult('blend', {
    links: [$('blend-download')],
    onError: (e) => say(`This browser would not keep the texture (${e?.message ?? e}): download it to keep it.`, 'warn'),
  });
  /** Offers the PNG `blob` (on the canvas already) for download, and says what it is. */
  function offerResult({ blob, file, info }) {
    if (resultUrl) URL.revokeObjectURL(resultUrl);
    resultUrl = URL.createObjectURL(blob);
    offerDownload($('blend-download'), resultUrl);
    zoom.reset(); // (after the picture is there: it enables the zoom)
    $('blend-download').download = file;
    $('blend-info').textContent = info;
  }
  result.restore().then(async (kept) => {
    if (!kept?.blob || runs.busy || resultUrl) return;
    const bitmap = await createImageBitmap(kept.blob).catch(() => null);
    if (!bitmap || runs.busy || resultUrl) return;
    const canvas = $('blend-result');
    [canvas.width, canvas.height] = [bitmap.width, bitmap.height];
    canvas.getContext('2d').drawImage(bitmap, 0, 0);
    offerResult(kept);
  });

  // The texture zooms (pixels shown as they are) and pans like the vector result.
  const zoom = zoomable($('blend-view'), {
    zoomIn: $('blend-zoom-in'), zoomOut: $('blend-zoom-out'), fit: $('blend-zoom-fit'), actual: $('blend-zoom-actual'), level: $('blend-zoom-level'),
    shown: () => $('blend-download').getAttribute('aria-disabled') !== 'true',
    // (The canvas's pixels are stretched over its box, borders excluded.)
    scale: () => $('blend-result').clientWidth / $('blend-result').width,
  });

  // --- start ---
  showMode();
  showAngle();
  const savedMask = load(maskKey, null);
  if (settings.transition === 'mask' && savedMask?.grey) {
    const { width, height, grey } = savedMask;
    const img = new ImageData(width, height);
    for (let i = 0; i < grey.length; i++) {
      img.data[4 * i] = img.data[4 * i + 1] = img.data[4 * i + 2] = grey[i];
      img.data[4 * i + 3] = 255;
    }
    createImageBitmap(img).then((bitmap) => mctx.drawImage(bitmap, 0, 0, mask.width, mask.height), drawShape);
  } else if (settings.transition === 'mask' && savedMask) {
    // (A data URL from an older page, or the PNG Blob an earlier one kept.)
    const blob = typeof savedMask === 'string' ? fetch(savedMask).then((r) => r.blob()) : Promise.resolve(savedMask);
    blob.then(createImageBitmap).then((bitmap) => mctx.drawImage(bitmap, 0, 0, mask.width, mask.height), drawShape);
  } else drawShape();
  for (const slot of Object.values(slots)) slot.picker.start();
}
