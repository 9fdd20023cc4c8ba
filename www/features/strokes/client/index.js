// Vector strokes tab: draw or import, see classes, synthesize in the worker, download.
import { Drawing, fitStrokes } from './canvas.js';
import { Autocomplete } from './autocomplete.js';
import { repeatPanel } from './repeat.js';
import { transformPeriods, transformStrokes } from './transform.js';
import { classColors, defaultOptions, defaultPen, defaultStyle, maxSide, palettes, sessionKey, storageKey, suggestCount } from '../shared/meta.js';
import { forget, load, store as save } from '../../../shared/storage.js';
import { get, saver } from '../../../shared/store.js';
import { offerDownload, runControls } from '../../../shared/run.js';
import { tilePanel } from '../../../shared/tile.js';
import { keptResult } from '../../../shared/results.js';
import { zoomable } from '../../../shared/zoom.js';
import { checkStyle, restyleSvg } from '../../../pkg/restyle.js';
import { sayInto } from '../../../shared/say.js';

const SETTINGS_KEY = 'patternsynth.strokes.settings.v1';

/** How the result tells which structure the drawing was repeated on. */
const STRUCTURE = {
  lattice: 'repeated on a lattice, ',
  ring: 'completed as a ring, ',
  curve: 'continued along its curve, ',
  sequence: 'continued as a sequence, ',
  irregular: 'no repeat (a mosaic of the drawing), ',
};

export function mountStrokes(root, client) {
  const $ = (id) => root.querySelector(`#${id}`);
  const canvas = $('draw');
  // The pen's width is `penWidth` in the settings: `width` is the output's.
  const { width: _penWidth, ...pen } = defaultPen;
  let settings = { ...defaultOptions, ...pen, ...defaultStyle, ...load(SETTINGS_KEY, {}) };
  // Settings saved by an earlier version could hold the pen's width as the output's.
  for (const k of ['width', 'height']) if (!(Number(settings[k]) >= 10)) settings[k] = defaultOptions[k];
  let classifyAbort = null;
  let resultUrl = null;

  const say = sayInto($('messages'));
  const runs = runControls({ run: $('synthesize'), cancel: $('cancel'), progress: $('progress'), say });

  // --- pen and settings inputs ---
  const bind = (id, key, parse = (v) => v, prop = 'value') => {
    const el = $(id);
    if (settings[key] !== null && settings[key] !== undefined) el[prop] = settings[key];
    el.addEventListener('input', () => {
      settings[key] = parse(el[prop]);
      save(SETTINGS_KEY, settings);
      if (key === 'width' && id === 'stroke-width') $('stroke-width-out').value = el.value;
    });
    return el;
  };
  bind('stroke-color', 'stroke');
  bind('stroke-on', 'strokeOn', Boolean, 'checked');
  bind('fill-color', 'fill');
  bind('fill-on', 'fillOn', Boolean, 'checked');
  const penWidth = $('stroke-width');
  penWidth.value = settings.penWidth ?? defaultPen.width;
  $('stroke-width-out').value = penWidth.value;
  penWidth.addEventListener('input', () => {
    settings.penWidth = Number(penWidth.value);
    $('stroke-width-out').value = penWidth.value;
    save(SETTINGS_KEY, settings);
  });
  bind('out-width', 'width', Number);
  bind('out-height', 'height', Number);
  bind('variation', 'variation', Boolean, 'checked');
  bind('regularize', 'regularize', Boolean, 'checked');
  bind('seed', 'seed', Number);
  bind('tile-repeats', 'tileRepeats', Number);
  bind('autocomplete', 'autocomplete', Boolean, 'checked');
  for (const [key, id] of [['pathTolerance', 'path'], ['widthTolerance', 'width'], ['colorTolerance', 'color']]) {
    const input = $(`tol-${id}`), auto = $(`auto-${id}`);
    auto.checked = settings[key] === null || settings[key] === undefined;
    if (!auto.checked) input.value = settings[key];
    input.disabled = auto.checked;
    const update = () => {
      input.disabled = auto.checked;
      settings[key] = auto.checked || input.value === '' ? null : Number(input.value);
      save(SETTINGS_KEY, settings);
      scheduleClassify();
      autocomplete?.update();
    };
    auto.addEventListener('change', update);
    input.addEventListener('input', update);
  }

  // --- the drawing, kept with its undo history in IndexedDB ---
  let autocomplete = null;
  const kept = saver(sessionKey, () => drawing.session, {
    onError: (e) => say(`This browser would not keep the drawing (${e?.message ?? e}): use "Export session" to keep it in a file.`, 'warn'),
    onSaved: () => say('The drawing is kept again.'),
  });
  addEventListener('pagehide', () => kept.flush());
  document.addEventListener('visibilitychange', () => { if (document.hidden) kept.flush(); });
  window.playground = { ...window.playground, drawing: () => drawing.session, latticeOrigin: () => drawing.latticeOrigin() };
  const drawing = new Drawing(canvas, {
    getPen: () => ({ width: Number(penWidth.value), stroke: settings.stroke, strokeOn: settings.strokeOn, fill: settings.fill, fillOn: settings.fillOn }),
    onChange: (strokes) => {
      kept.save();
      $('stroke-count').textContent = `${strokes.length} stroke${strokes.length === 1 ? '' : 's'}`;
      scheduleClassify();
      autocomplete?.update();
    },
    onTap: () => {
      if (!autocomplete.ghosts().length) return false;
      autocomplete.accept();
      return true;
    },
  });
  const layout = repeatPanel({ $, settings, save: (s) => save(SETTINGS_KEY, s), drawing });
  // Tab accepts ghosts once after drawing (the hand is on the canvas); a keyboard user
  // who tabs onto the canvas accepts with Enter, and Tab moves on: no trap.
  let tabAccepts = false;
  canvas.addEventListener('pointerdown', () => {
    canvas.focus();
    tabAccepts = true;
  });
  // (Once focus has left the canvas, Tab back onto it and Tab again moves on: it
  // accepted the ghosts left from the drawing, 4 strokes became 7.)
  canvas.addEventListener('blur', () => { tabAccepts = false; });
  $('undo').addEventListener('click', () => drawing.undo());
  $('redo').addEventListener('click', () => drawing.redo());
  $('clear').addEventListener('click', () => drawing.set([]));
  document.addEventListener('keydown', (e) => {
    // (Nor while another tab keeps the work and this page is read-only: tab-lock.js.)
    if (root.hidden || root.closest('[inert]')) return;
    // Tab, Enter and Escape act on ghosts only while the canvas has focus and ghosts are
    // shown; otherwise Tab moves focus through the page as everywhere else.
    const onCanvas = document.activeElement === canvas;
    const accepting = e.key === 'Enter' || (e.key === 'Tab' && !e.shiftKey && tabAccepts);
    if (accepting && onCanvas && autocomplete.ghosts().length) {
      e.preventDefault();
      autocomplete.accept();
      tabAccepts = false;
      return;
    }
    if (e.key === 'Escape' && onCanvas && autocomplete.dismiss()) return void e.preventDefault();
    if (!(e.ctrlKey || e.metaKey) || e.key.toLowerCase() !== 'z') return;
    e.preventDefault();
    if (e.shiftKey) drawing.redo(); else drawing.undo();
  });

  // --- autocomplete ---
  autocomplete = new Autocomplete({
    client,
    drawing,
    options: () => ({ count: suggestCount, variation: settings.variation, seed: Number(settings.seed) || 0, ...tolerances() }),
    enabled: () => settings.autocomplete !== false,
    busy: () => runs.busy,
    onState: ({ count, reason, pending }) => {
      // Lets a test (or a screen reader, via aria-busy) tell a settled answer from one under way.
      $('suggest-status').setAttribute('aria-busy', String(pending));
      $('accept-ghosts').disabled = !count;
      $('dismiss-ghosts').disabled = !count;
      const touch = document.documentElement.classList.contains('touch');
      $('suggest-status').textContent = count
        ? `${count} suggested stroke${count === 1 ? '' : 's'}: ${touch ? 'tap a ghost or Accept to add them.' : 'Tab (after drawing), Enter or a tap on a ghost accepts them, Esc dismisses them.'}`
        : settings.autocomplete === false ? '' : reason ?? '';
    },
  });
  $('autocomplete').addEventListener('change', () => autocomplete.update());
  $('accept-ghosts').addEventListener('click', () => autocomplete.accept());
  $('dismiss-ghosts').addEventListener('click', () => autocomplete.dismiss());
  $('fill-canvas').addEventListener('click', async () => {
    if (runs.busy) return say('Wait for the synthesis to finish, or cancel it.', 'warn');
    $('fill-canvas').disabled = true;
    try {
      const { added, reason } = await autocomplete.fill();
      if (added) say(`Filled the canvas: ${added} strokes added (Undo takes them back).`);
      else say(reason ?? 'Nothing to add.', 'warn');
    } catch (e) {
      say(e.message, 'error');
    } finally {
      $('fill-canvas').disabled = false;
    }
  });
  $('show-classes').addEventListener('change', () => scheduleClassify(0));

  // --- classes ---
  let classifyTimer = 0;
  /** The drawing's latest classes: the colour swatches of a tile made before any result. */
  let lastClassification = null;
  function scheduleClassify(delay = 250) {
    clearTimeout(classifyTimer);
    classifyTimer = setTimeout(classify, delay);
  }
  async function classify() {
    classifyAbort?.abort();
    const strokes = drawing.strokes;
    if (!strokes.length || !$('show-classes').checked) {
      drawing.showClasses(null, classColors);
      $('legend').replaceChildren();
      return;
    }
    if (runs.busy) return; // the worker is busy synthesizing; classes update afterwards
    classifyAbort = new AbortController();
    try {
      const c = await client.classifyStrokes(strokes, tolerances(), { signal: classifyAbort.signal });
      if (strokes !== drawing.strokes) return;
      lastClassification = { strokes, classification: c };
      drawing.showClasses(c.classes, classColors);
      const counts = new Map();
      c.classes.forEach((k) => counts.set(k, (counts.get(k) ?? 0) + 1));
      $('legend').replaceChildren(...[...counts].map(([k, n]) => {
        const chip = document.createElement('span');
        chip.className = 'chip';
        chip.innerHTML = `<span class="swatch" style="background:${classColors[k % classColors.length]}"></span>class ${k + 1}: ${n}`;
        return chip;
      }));
      for (const [id, key] of [['path', 'path'], ['width', 'width'], ['color', 'color']]) {
        $(`tol-${id}`).placeholder = c.proposed[key].toFixed(2);
        if ($(`auto-${id}`).checked) $(`tol-${id}`).value = '';
      }
    } catch (e) {
      if (e.name !== 'AbortError') say(e.message, 'error');
    }
  }
  const tolerances = () => {
    const o = {};
    for (const k of ['pathTolerance', 'widthTolerance', 'colorTolerance']) if (settings[k] !== null && settings[k] !== undefined) o[k] = settings[k];
    return o;
  };

  // --- import and examples ---
  const importSvg = async (text) => {
    try {
      const r = await client.parseSvgReport(text);
      if (!r.strokes.length) return say('That SVG has no shapes to use as strokes.', 'warn');
      drawing.set(fitStrokes(r.strokes, drawing.logical.w, drawing.logical.h));
      say(`Imported ${r.strokes.length} strokes.${r.warnings.length ? ' ' + r.warnings.join(' ') : ''}`, r.warnings.length ? 'warn' : '');
    } catch (e) {
      say(e.message, 'error');
    }
  };
  $('import-svg').addEventListener('change', async (e) => {
    const file = e.target.files[0];
    if (file) await importSvg(await file.text());
    e.target.value = '';
  });
  const zone = $('drop-zone');
  zone.addEventListener('dragover', (e) => { e.preventDefault(); zone.classList.add('dragging'); });
  zone.addEventListener('dragleave', () => zone.classList.remove('dragging'));
  zone.addEventListener('drop', async (e) => {
    e.preventDefault();
    zone.classList.remove('dragging');
    const file = e.dataTransfer.files[0];
    if (file) await importSvg(await file.text());
  });
  let examples = null;
  // Built-in drawings: a static file (written by `cargo run --example export_examples`).
  const loadExamples = async () => (examples ??= await (await fetch(new URL('../shared/examples.json', import.meta.url))).json());
  loadExamples().then((list) => {
    const select = $('examples');
    for (const { name } of list) select.append(new Option(name, name));
  });
  $('examples').addEventListener('change', async (e) => {
    const ex = (await loadExamples()).find((x) => x.name === e.target.value);
    e.target.value = '';
    if (ex) drawing.set(fitStrokes(ex.strokes, drawing.logical.w, drawing.logical.h, 60));
  });

  // --- synthesis ---
  $('synthesize').addEventListener('click', async () => {
    const width = Number(settings.width), height = Number(settings.height);
    if (!(width >= 10 && height >= 10 && width <= maxSide && height <= maxSide)) {
      return say(`Output width and height must be between 10 and ${maxSide}.`, 'error');
    }
    const t0 = performance.now();
    await runs.start('Synthesizing…', async (call) => {
      const turn = { scale: Number(settings.resultScale) || 1, degrees: Number(settings.resultRotate) || 0 };
      const opts = { width, height, variation: settings.variation, regularize: settings.regularize !== false, seed: Number(settings.seed) || 0, periods: transformPeriods(layout.periods(), turn), ...tolerances() };
      // The worker draws the preview and keeps the strokes: reading tens of thousands of
      // them, or parsing and painting their SVG, would freeze this page for most of a second.
      const box = $('preview').clientWidth * devicePixelRatio || 800;
      const fit = Math.min(1, 4096 / Math.max(width, height), box / width);
      const { background, opacity } = currentStyle();
      const preview = { width: Math.ceil(width * fit), height: Math.ceil(height * fit), background: background ?? undefined, opacity };
      const strokes = transformStrokes(drawing.strokes, turn);
      const r = await client.synthesizeStrokes(strokes, opts, { ...call, fields: ['svgBlob', 'classes', 'classification', 'periods', 'structure'], preview, keep: true });
      // (In the drawing's own frame: a layout set by hand starts from them.)
      layout.found(transformPeriods(r.periods, { scale: 1 / turn.scale, degrees: -turn.degrees }));
      shownResult = { strokes, opts, preview, classification: r.classification };
      $('download-png').disabled = false;
      const ms = performance.now() - t0;
      zoom.reset();
      showResult(r, width, height);
      classColorInputs(strokes, r.classification);
      $('style').disabled = false;
      // A style chosen before (a palette, a background) applies to the new result too
      // (the preview was drawn with its background and opacity, not the SVG).
      if (styleChanged()) await restyle();
      $('result-info').textContent = `${r.classes.length} strokes, ${r.classification.count} classes, ${STRUCTURE[r.structure] ?? ''}${width}×${height}, ${ms.toFixed(0)} ms`;
      resultKept.keep({ svgBlob: r.svgBlob, ...shownResult, info: $('result-info').textContent });
      say('Done.');
    });
    scheduleClassify(0);
    autocomplete.update();
  });

  // --- the result shown, restyled in the worker (colours, background, opacity) ---
  let shownResult = null;
  const zoom = zoomable($('preview'), {
    zoomIn: $('zoom-in'), zoomOut: $('zoom-out'), fit: $('zoom-fit'), level: $('zoom-level'),
    // Zoomed in, the kept result is drawn again at that scale (up to 8192 px a side).
    onSettle: () => { restyling = restyle(); },
  });
  /** The preview's size at the current zoom. */
  const previewSize = () => {
    const { width, height, ...rest } = shownResult.preview;
    const k = Math.min(zoom.zoom, 8192 / Math.max(width, height));
    return { ...rest, width: Math.ceil(width * k), height: Math.ceil(height * k) };
  };
  window.playground = { ...window.playground, zoom: () => zoom.zoom };
  /** Shows a result's (or restyled result's) preview and offers its SVG. */
  function showResult(r, width, height) {
    if (resultUrl) URL.revokeObjectURL(resultUrl);
    resultUrl = URL.createObjectURL(r.svgBlob);
    let shown;
    if (r.preview) {
      shown = document.createElement('canvas');
      [shown.width, shown.height] = [r.preview.width, r.preview.height];
      shown.getContext('bitmaprenderer').transferFromImageBitmap(r.preview);
    } else {
      shown = new Image();
      shown.src = resultUrl;
    }
    shown.setAttribute('role', 'img');
    shown.setAttribute('aria-label', `Synthesized pattern, ${width} × ${height}`);
    $('preview').replaceChildren(shown);
    offerDownload($('download'), resultUrl);
    $('download').download = `pattern-${width}x${height}.svg`;
  }
  const palette = $('palette');
  palette.append(...Object.keys(palettes).map((name) => new Option(name, name)));
  palette.value = settings.palette in palettes ? settings.palette : defaultStyle.palette;
  $('bg-on').checked = settings.backgroundOn !== false;
  $('bg-color').value = settings.background;
  $('opacity').value = settings.opacity;
  $('opacity-out').value = `${Math.round(settings.opacity * 100)}%`;
  /** Each class's colour: chosen by hand (`picked`), else the palette's, else as drawn. */
  let drawnColors = [];
  let picked = [];
  function classColorInputs(strokes, classification) {
    drawnColors = [];
    classification.classes.forEach((k, i) => { drawnColors[k] ??= strokes[i].stroke ?? strokes[i].fill ?? '#000000'; });
    picked = [];
    // The twelve first classes get a swatch each; a palette colours them all.
    $('class-colors').replaceChildren(...drawnColors.slice(0, 12).map((_, k) => {
      const input = Object.assign(document.createElement('input'), { type: 'color', value: colorOf(k) });
      input.setAttribute('aria-label', `Colour of class ${k + 1}`);
      input.title = `Class ${k + 1}`;
      input.addEventListener('input', () => { picked[k] = input.value; scheduleRestyle(); });
      return input;
    }));
  }
  function colorOf(k) {
    const p = palettes[palette.value] ?? [];
    return picked[k] ?? (p.length ? p[k % p.length] : drawnColors[k]);
  }
  const currentStyle = () => ({
    colors: drawnColors.map((drawn, k) => (colorOf(k) === drawn ? null : colorOf(k))),
    background: $('bg-on').checked ? $('bg-color').value : null,
    opacity: Number($('opacity').value),
  });
  const styleChanged = () => {
    const st = currentStyle();
    return st.colors.some(Boolean) || st.background !== null || st.opacity !== 1;
  };
  /** The kept result in the current style; a worker that lost it (an aborted call
   *  starts a fresh one) makes it again with the same options and seed. */
  async function styled(preview) {
    try {
      return await client.restyle(currentStyle(), preview);
    } catch (e) {
      if (!/Nothing to restyle/.test(e.message)) throw e;
      await client.synthesizeStrokes(shownResult.strokes, shownResult.opts, { fields: [], keep: true });
      return client.restyle(currentStyle(), preview);
    }
  }
  let restyleTimer = 0;
  let restyling = Promise.resolve();
  function scheduleRestyle() {
    settings.palette = palette.value;
    settings.backgroundOn = $('bg-on').checked;
    settings.background = $('bg-color').value;
    settings.opacity = Number($('opacity').value);
    $('opacity-out').value = `${Math.round(settings.opacity * 100)}%`;
    save(SETTINGS_KEY, settings);
    for (const [k, input] of [...$('class-colors').children].entries()) input.value = colorOf(k);
    showTile();
    clearTimeout(restyleTimer);
    if (shownResult) restyleTimer = setTimeout(() => { restyling = restyle(); }, 60);
  }
  async function restyle() {
    if (!shownResult) return;
    const { opts } = shownResult;
    try {
      const r = await styled(previewSize());
      showResult(r, opts.width, opts.height);
    } catch (e) {
      say(e.message, 'error');
    }
  }
  palette.addEventListener('change', () => { picked = []; scheduleRestyle(); });
  for (const id of ['bg-on', 'bg-color', 'opacity']) $(id).addEventListener('input', scheduleRestyle);
  $('style-reset').addEventListener('click', () => {
    picked = [];
    palette.value = defaultStyle.palette;
    $('bg-on').checked = defaultStyle.backgroundOn;
    $('bg-color').value = defaultStyle.background;
    $('opacity').value = defaultStyle.opacity;
    scheduleRestyle();
  });
  window.playground = { ...window.playground, restyled: () => restyling };

  // A PNG of the result shown, in its style, at a chosen width: drawn and encoded in the
  // worker from the kept result (nothing synthesized again).
  $('download-png').addEventListener('click', async () => {
    if (!shownResult) return;
    const { opts } = shownResult;
    const width = Math.round(Number($('png-width').value));
    if (!(width >= 16 && width <= 8192)) return say('The PNG width must be from 16 to 8192 pixels.', 'error');
    const height = Math.max(1, Math.round((width * opts.height) / opts.width));
    if (height > 8192) return say(`At ${width} pixels wide the PNG would be ${height} tall; the most is 8192.`, 'error');
    $('download-png').disabled = true;
    try {
      say(`Drawing a ${width}×${height} PNG…`);
      const r = await styled({ width, height, type: 'image/png' });
      if (!r.preview) throw new Error('This browser cannot draw in a worker (no OffscreenCanvas); download the SVG instead.');
      const a = Object.assign(document.createElement('a'), { href: URL.createObjectURL(r.preview), download: `pattern-${opts.width}x${opts.height}-${width}px.png` });
      a.click();
      setTimeout(() => URL.revokeObjectURL(a.href), 10_000);
      say(`PNG ready: ${width}×${height}.`);
    } catch (e) {
      say(e.message, 'error');
    } finally {
      $('download-png').disabled = false;
    }
  });

  // --- seamless tile (in the result's colours: the page restyles its small SVG itself) ---
  let tileUrl = null;
  let shownTile = null;
  function showTile() {
    if (!shownTile) return;
    const { t, scale, size } = shownTile;
    const svg = restyleSvg(t.svg, checkStyle(currentStyle()));
    if (tileUrl) URL.revokeObjectURL(tileUrl);
    tileUrl = URL.createObjectURL(new Blob([svg], { type: 'image/svg+xml' }));
    const transform = { scale: Number($('tile-scale').value), rotate: Number($('tile-rotate').value) };
    tile.show({ url: tileUrl, svg, file: `tile-${size}.svg`, width: t.width, height: t.height, scale, transform });
  }
  // Scale and rotation of the pattern: of the tile, its preview and CSS (not the tile
  // file); of the result, the drawing it is synthesized from (transform.js).
  const sliders = [['tile-scale', 'tileScale', '%'], ['tile-rotate', 'tileRotate', '°'], ['out-scale', 'resultScale', '%'], ['out-rotate', 'resultRotate', '°']];
  for (const [id, key, unit] of sliders) {
    const input = $(id);
    if (settings[key] !== undefined) input.value = settings[key];
    const show = () => { $(`${id}-out`).value = unit === '%' ? `${Math.round(input.value * 100)}%` : `${input.value}°`; };
    show();
    input.addEventListener('input', () => {
      settings[key] = Number(input.value);
      save(SETTINGS_KEY, settings);
      show();
      if (id.startsWith('tile-')) showTile();
    });
  }
  const tile = tilePanel({ preview: $('tile-preview'), download: $('tile-download'), css: $('tile-css'), copy: $('tile-copy'), offset: $('tile-offset') });
  $('make-tile').addEventListener('click', async () => {
    $('make-tile').disabled = true;
    // A refusal must not leave the previous tile on screen as if it were this one's.
    tile.clear();
    shownTile = null;
    $('tile-info').textContent = 'Making the tile…';
    try {
      const opts = { variation: settings.variation, seed: Number(settings.seed) || 0, repeats: Number(settings.tileRepeats) || 1, periods: layout.periods(), ...tolerances() };
      const t = await client.strokeTile(drawing.strokes, opts);
      // Shown 3 x 3, scaled to the column (at most 4x); one tile outlined.
      const scale = Math.min(4, ($('tile-preview').parentElement.clientWidth - 24) / (3 * t.width));
      shownTile = { t, scale, size: `${Math.round(t.width)}x${Math.round(t.height)}` };
      if (!shownResult && lastClassification?.strokes === drawing.strokes) classColorInputs(lastClassification.strokes, lastClassification.classification);
      $('style').disabled = false;
      showTile();
      $('tile-info').textContent = `${+t.width.toFixed(2)}×${+t.height.toFixed(2)} tile, ${t.sites} elements (${t.strokes.length} strokes with the edge copies), shown 3×3.`;
      tileKept.keep({ ...shownTile, info: $('tile-info').textContent });
      say('Tile ready.');
    } catch (e) {
      $('tile-info').textContent = 'No tile: see the message above.';
      say(e.message, 'error');
    } finally {
      $('make-tile').disabled = false;
    }
  });

  // --- start: the kept drawing (or one kept by an older page, in localStorage), or an
  // example so the page does something at once ---
  // --- the result and the tile, kept across reloads (shared/results.js) ---
  const unkept = (what) => (e) => say(`This browser would not keep the ${what} (${e?.message ?? e}): download it to keep it.`, 'warn');
  const resultKept = keptResult('strokes', { links: [$('download')], onError: unkept('result') });
  const tileKept = keptResult('strokes-tile', { links: [$('tile-download')], onError: unkept('tile') });
  const restoreResults = () => resultKept.restore().then((kept) => {
    if (!kept?.svgBlob || runs.busy || shownResult) return;
    const { svgBlob, info, ...result } = kept;
    shownResult = result;
    $('download-png').disabled = false;
    showResult({ svgBlob }, result.opts.width, result.opts.height);
    classColorInputs(result.strokes, result.classification);
    $('style').disabled = false;
    $('result-info').textContent = info;
    // (Restyled by the worker, which makes the result again first: same options and seed.)
    if (styleChanged()) restyling = restyle();
  }).then(() => tileKept.restore()).then((kept) => {
    if (!kept?.t || shownTile || $('make-tile').disabled) return;
    const { info, ...made } = kept;
    shownTile = made;
    $('style').disabled = false;
    showTile();
    $('tile-info').textContent = info;
  });

  const legacy = load(storageKey, null);
  // (The result and the tile after the drawing: read first, a large result delayed it.)
  get(sessionKey).catch(() => undefined).then(async (session) => {
    if (session && (session.strokes?.length || session.past?.length)) return drawing.restore(session);
    if (Array.isArray(legacy) && legacy.length) {
      drawing.set(legacy, { record: false });
      await kept.flush();
      return forget(storageKey);
    }
    const list = await loadExamples();
    const ex = list.find((x) => x.name === 'classes-by-shape') ?? list[0];
    if (ex && !drawing.strokes.length) drawing.set(fitStrokes(ex.strokes, drawing.logical.w, drawing.logical.h, 60), { record: false });
  }).finally(restoreResults);
}
