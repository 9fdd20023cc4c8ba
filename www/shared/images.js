// Image input for the raster tabs: built-in photographs, opened or dropped files, and
// keeping what the person opened across reloads (the file's Blob in IndexedDB).
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

/** Keeps the file the person opened under `key` (its Blob, as it is, in IndexedDB:
 *  written at once, so a reload right after finds it; re-encoding the canvas first
 *  took about a second, and a reload within it lost the picture 3-4 times in 12);
 *  false when the browser will not keep it. */
export async function keepImage(key, name, blob) {
  try {
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

/**
 * One picture input of a raster tab: a select of built-in photographs, an Open… file
 * input and a drop zone; a picture the person opened is kept under `key` and comes
 * back after a reload, a built-in one is named in `settings[setting]` ('' for an opened
 * one). `show(rgba)` puts it on the page; `say(text, kind)` reports, naming the picture
 * `as` (the Blend tab's "texture A") where a tab has several.
 */
export function imagePicker({ select, file, drop, textures, fallback, maxSide, key, settings, setting = 'texture', save, say, show, noun = 'image', as = '' }) {
  select.append(new Option('Built-in…', ''), ...textures.map((t) => new Option(t, t)));
  /** Shows a bitmap, scaled down to the cap; returns the note saying so (empty when it fits). */
  function use(bitmap, name) {
    const { rgba, scaledFrom } = rgbaOf(bitmap, maxSide);
    const note = scaledFrom
      ? `${name}: scaled from ${scaledFrom[0]}×${scaledFrom[1]} to ${rgba.width}×${rgba.height} (${noun}s are capped at ${maxSide} px to keep synthesis quick).`
      : '';
    if (note) say(note, 'warn');
    show(rgba);
    return note;
  }
  // The picture asked for last wins: a built-in one still loading when a file is opened
  // (a slow network, a busy machine) must not replace the file when it arrives. Each
  // request takes a ticket; what arrives for an older one is dropped.
  let latest = 0;
  async function builtin(name) {
    const ticket = ++latest;
    try {
      const bitmap = await builtinBitmap(name);
      if (ticket === latest) use(bitmap, name);
    } catch (e) {
      if (ticket === latest) say(`Could not load the built-in ${noun} '${name}': ${e.message}`, 'error');
    }
  }
  async function open(f) {
    const ticket = ++latest;
    const bitmap = await fileBitmap(f);
    if (ticket !== latest) return;
    if (!bitmap) return say(`${f.name} is not an image this browser can read (use PNG or JPEG).`, 'error');
    const note = use(bitmap, f.name);
    select.value = '';
    settings[setting] = '';
    save();
    const kept = await keepImage(key, f.name, f);
    // (The scaling note stays in the message: it is what the person most needs to know.)
    say(`Loaded ${f.name}${as ? ` as ${as}` : ''}.${note ? ` ${note}` : ''}${kept ? '' : ' (This browser would not keep it: it will not survive a reload.)'}`, kept && !note ? '' : 'warn');
  }
  select.addEventListener('change', () => {
    if (!select.value) return;
    settings[setting] = select.value;
    save();
    forgetImage(key);
    builtin(select.value);
  });
  file.addEventListener('change', async (e) => {
    if (e.target.files[0]) await open(e.target.files[0]);
    e.target.value = '';
  });
  onDropFile(drop, open);
  return {
    /** Shows the picture the settings name, the one kept, or `fallback`. */
    async start() {
      if (!settings[setting]) {
        const ticket = ++latest;
        const kept = await keptImage(key);
        // (Something picked meanwhile stands.)
        if (ticket !== latest) return;
        if (kept) return void use(kept.bitmap, kept.name);
      }
      select.value = settings[setting] || fallback;
      await builtin(select.value);
    },
  };
}
