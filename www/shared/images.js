// Image input for the raster tabs: built-in photographs, opened or dropped files, and
// keeping what the person opened across reloads (as a PNG data URL).
import { forget, load, store } from './storage.js';

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

/** Keeps `canvas`'s picture under `key`; false when storage is full. */
export function keepImage(key, name, canvas) {
  return store(key, { name, url: canvas.toDataURL('image/png') });
}

/** The picture kept under `key` as `{ name, bitmap }`, or null. */
export async function keptImage(key) {
  const kept = load(key, null);
  if (!kept) return null;
  try {
    return { name: kept.name, bitmap: await createImageBitmap(await (await fetch(kept.url)).blob()) };
  } catch {
    forget(key);
    return null;
  }
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
