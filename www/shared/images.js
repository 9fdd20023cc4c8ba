// Image input for the raster tabs: built-in photographs, opened or dropped files, and
// keeping what the person opened across reloads (a PNG Blob in IndexedDB).
import { forget, load } from './storage.js';
import { del, get, set } from './store.js';

/** RGBA pixels of a bitmap, scaled down uniformly when a side exceeds `maxSide`;
 *  `scaledFrom` is the original size when it was. */
export function rgbaOf(bitmap, maxSide) {
  let { width, height } = bitmap;
  const from = [width, height];
  const k = Math.min(1, maxSide / Math.max(width, height));
  if (k < 1) {
    width = Math.max(1, Math.round(width * k));
    height = Math.max(1, Math.round(height * k));
  }
  const ctx = new OffscreenCanvas(width, height).getContext('2d');
  ctx.drawImage(bitmap, 0, 0, width, height);
  return { rgba: { width, height, data: ctx.getImageData(0, 0, width, height).data }, scaledFrom: k < 1 ? from : null };
}

/** A built-in texture (www/textures/<name>.png). */
export async function builtinBitmap(name) {
  const response = await fetch(new URL(`../textures/${name}.png`, import.meta.url));
  if (!response.ok) throw new Error(`HTTP ${response.status}`);
  return createImageBitmap(await response.blob());
}

/** A file's bitmap, or null when the browser cannot read it as an image. */
export async function fileBitmap(file) {
  try {
    return await createImageBitmap(file);
  } catch {
    return null;
  }
}

/** Keeps `canvas`'s picture under `key` (a PNG Blob in IndexedDB); false when the
 *  browser will not keep it. */
export async function keepImage(key, name, canvas) {
  try {
    const blob = await new Promise((ok, fail) => canvas.toBlob((b) => (b ? ok(b) : fail(new Error('no PNG'))), 'image/png'));
    await set(key, { name, blob });
    forget(key);
    return true;
  } catch {
    return false;
  }
}

/** The picture kept under `key` as `{ name, bitmap }`, or null (one an older page kept
 *  in localStorage as a data URL moves to IndexedDB). */
export async function keptImage(key) {
  try {
    let kept = await get(key).catch(() => undefined);
    if (!kept) {
      const legacy = load(key, null);
      if (!legacy) return null;
      kept = { name: legacy.name, blob: await (await fetch(legacy.url)).blob() };
      await set(key, kept).then(() => forget(key), () => {});
    }
    return { name: kept.name, bitmap: await createImageBitmap(kept.blob) };
  } catch {
    await forgetImage(key);
    return null;
  }
}

/** Forgets the picture kept under `key`. */
export async function forgetImage(key) {
  forget(key);
  await del(key).catch(() => {});
}

/** Drag-and-drop of one file onto `zone`. */
export function onDropFile(zone, handle) {
  zone.addEventListener('dragover', (e) => { e.preventDefault(); zone.classList.add('dragging'); });
  zone.addEventListener('dragleave', () => zone.classList.remove('dragging'));
  zone.addEventListener('drop', (e) => {
    e.preventDefault();
    zone.classList.remove('dragging');
    if (e.dataTransfer.files[0]) handle(e.dataTransfer.files[0]);
  });
}
