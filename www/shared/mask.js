// A mask painted over an image: a transparent canvas over the picture, painted in
// translucent magenta with a round brush (pointer: mouse, pen, finger) or from the
// keyboard (`keyboardBrush`, the blend's mask's too: the arrows move a brush ring, Space
// or Enter paints there, Shift + an arrow moves while painting). Erase, clear, and the mask kept in IndexedDB (one byte a
// pixel, written at once after each stroke by `saver`, so a reload right after a stroke
// finds it). The engines read it as a mask image: opaque white = masked.
import { del, get, saver } from './store.js';

const INK = 'rgba(230, 0, 160, 0.55)';

/** `overlay`: the canvas over the image; `brush`: a range input (brush diameter in
 *  image pixels); `erase`: a checkbox; `clear`: a button; `key`: where the mask is kept;
 *  `onChange()`: after each stroke. */
export function maskPainter({ overlay, brush, erase, clear, key, onChange = () => {}, onError }) {
  const ctx = overlay.getContext('2d', { willReadFrequently: true });
  let painting = false;
  const bits = () => {
    const d = ctx.getImageData(0, 0, overlay.width, overlay.height).data;
    const on = new Uint8Array(overlay.width * overlay.height);
    for (let i = 0; i < on.length; i++) on[i] = d[4 * i + 3] > 0 ? 1 : 0;
    return on;
  };
  const writer = saver(key, () => ({ width: overlay.width, height: overlay.height, bits: bits() }), { onError });
  // (A stroke's write waits for the task to end: a reload right after it must find it.)
  addEventListener('pagehide', () => writer.flush());
  document.addEventListener('visibilitychange', () => { if (document.hidden) writer.flush(); });

  // Each dab replaces what is under it by the ink (cut out, then inked), so strokes
  // over strokes do not darken: the mask is a set of pixels, not a shade.
  const dab = (x, y) => {
    ctx.save();
    ctx.beginPath();
    ctx.arc(x, y, Number(brush.value) / 2, 0, Math.PI * 2);
    ctx.globalCompositeOperation = 'destination-out';
    ctx.fill();
    if (!erase.checked) {
      ctx.globalCompositeOperation = 'source-over';
      ctx.fillStyle = INK;
      ctx.fill();
    }
    ctx.restore();
  };
  const line = (from, to) => dabsBetween(from, to, Number(brush.value), dab);
  const at = (e) => {
    const r = overlay.getBoundingClientRect();
    return [((e.clientX - r.left) * overlay.width) / r.width, ((e.clientY - r.top) * overlay.height) / r.height];
  };
  const keep = () => {
    writer.save();
    onChange();
  };

  let last = null;
  overlay.addEventListener('pointerdown', (e) => {
    painting = true;
    overlay.setPointerCapture(e.pointerId);
    last = at(e);
    dab(...last);
  });
  overlay.addEventListener('pointermove', (e) => {
    if (!painting) return;
    const p = at(e);
    line(last, p);
    last = p;
  });
  const end = () => {
    if (!painting) return;
    painting = false;
    keep();
  };
  overlay.addEventListener('pointerup', end);
  overlay.addEventListener('pointercancel', end);

  keyboardBrush({ canvas: overlay, brush, dab, done: keep });
  clear.addEventListener('click', () => {
    ctx.clearRect(0, 0, overlay.width, overlay.height);
    del(key).catch(() => {});
    onChange();
  });

  return {
    /** Sizes the mask to an image `width x height`, keeping what was painted (scaled)
     *  when `keepPainted`. */
    resize(width, height, keepPainted = false) {
      if (overlay.width === width && overlay.height === height) return;
      // (A mask painted over another photograph is dropped with it, and forgotten: kept,
      // it came back stretched over the new one after a reload, and the page still
      // said "painted" over an empty mask.)
      const dropped = !keepPainted && bits().includes(1);
      const old = keepPainted ? new OffscreenCanvas(overlay.width, overlay.height) : null;
      old?.getContext('2d').drawImage(overlay, 0, 0);
      overlay.width = width;
      overlay.height = height;
      if (old) ctx.drawImage(old, 0, 0, width, height);
      if (dropped) {
        del(key).catch(() => {});
        onChange();
      }
    },
    /** Reads back the mask kept under `key`, drawn at this size; false when none. */
    async restore() {
      try {
        const kept = await get(key);
        if (!kept?.bits) return false;
        const img = new ImageData(kept.width, kept.height);
        kept.bits.forEach((on, i) => on && img.data.set([230, 0, 160, 140], 4 * i));
        const c = new OffscreenCanvas(kept.width, kept.height);
        c.getContext('2d').putImageData(img, 0, 0);
        ctx.clearRect(0, 0, overlay.width, overlay.height);
        ctx.drawImage(c, 0, 0, overlay.width, overlay.height);
        onChange();
        return true;
      } catch {
        return false;
      }
    },
    /** Whether anything is painted. */
    painted: () => bits().includes(1),
    /** The mask as the engines read it: opaque white where painted, else black. */
    image() {
      const d = ctx.getImageData(0, 0, overlay.width, overlay.height).data;
      const out = new Uint8ClampedArray(d.length);
      for (let i = 0; i < d.length; i += 4) {
        const v = d[i + 3] > 0 ? 255 : 0;
        out[i] = out[i + 1] = out[i + 2] = v;
        out[i + 3] = 255;
      }
      return { width: overlay.width, height: overlay.height, data: out };
    },
    /** The mask painted programmatically (tests, examples): `fill(x, y)` true = masked. */
    paint(fill) {
      const img = ctx.createImageData(overlay.width, overlay.height);
      for (let y = 0; y < overlay.height; y++) for (let x = 0; x < overlay.width; x++) {
        if (fill(x, y)) img.data.set([230, 0, 160, 140], 4 * (y * overlay.width + x));
      }
      ctx.putImageData(img, 0, 0);
      keep();
    },
  };
}

/** Dabs of a brush `diameter` wide from `from` to `to` (not at `from`), a quarter of it apart. */
export function dabsBetween(from, to, diameter, dab) {
  const steps = Math.max(1, Math.ceil(Math.hypot(to[0] - from[0], to[1] - from[1]) / Math.max(1, diameter / 4)));
  for (let i = 1; i <= steps; i++) dab(from[0] + ((to[0] - from[0]) * i) / steps, from[1] + ((to[1] - from[1]) * i) / steps);
}

/**
 * Painting a focusable `canvas` from the keyboard: the arrows move the brush (a ring
 * shows where: its parent, positioned, gets the class `ring`), Space or Enter paints
 * there, Shift + an arrow paints as it moves. `brush`: the range input of the brush's
 * diameter in canvas pixels; `dab(x, y)` paints one dab; `done()` after each paint.
 */
export function keyboardBrush({ canvas, brush, dab, done }) {
  let cursor = null;
  const ring = () => {
    const box = canvas.parentElement;
    box.classList.toggle('ring', Boolean(cursor) && document.activeElement === canvas);
    if (!cursor) return;
    box.style.setProperty('--ring-x', `${(100 * cursor[0]) / canvas.width}%`);
    box.style.setProperty('--ring-y', `${(100 * cursor[1]) / canvas.height}%`);
    box.style.setProperty('--ring-size', `${(100 * Number(brush.value)) / canvas.width}%`);
  };
  canvas.addEventListener('focus', () => { cursor ??= [canvas.width / 2, canvas.height / 2]; ring(); });
  canvas.addEventListener('blur', () => canvas.parentElement.classList.remove('ring'));
  canvas.addEventListener('keydown', (e) => {
    const step = Math.max(2, Number(brush.value) / 2);
    const move = { ArrowLeft: [-step, 0], ArrowRight: [step, 0], ArrowUp: [0, -step], ArrowDown: [0, step] }[e.key];
    if (move) {
      e.preventDefault();
      const from = cursor ?? [canvas.width / 2, canvas.height / 2];
      cursor = [Math.min(canvas.width, Math.max(0, from[0] + move[0])), Math.min(canvas.height, Math.max(0, from[1] + move[1]))];
      if (e.shiftKey) {
        dabsBetween(from, cursor, Number(brush.value), dab);
        done();
      }
      ring();
    } else if (e.key === ' ' || e.key === 'Enter') {
      e.preventDefault();
      cursor ??= [canvas.width / 2, canvas.height / 2];
      dab(...cursor);
      done();
    }
  });
  brush.addEventListener('input', ring);
}
