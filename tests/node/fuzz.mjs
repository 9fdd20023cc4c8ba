// A seeded mutation fuzzer over the package's whole API: SVG documents (real pattern
// tiles and hand-made ones using use, CSS, gradients, transforms, arcs), PNG and JPEG
// files, strokes, images and option objects, mutated by flipping, cutting and
// duplicating bytes, nesting deeply and planting huge numbers, and at the level of
// structure: selector chains over deep nesting, entity graphs, huge attribute and
// declaration counts, Proxies and throwing getters in options and strokes, progress
// callbacks that call the engine again, detached and shared buffers. Every call must
// return or throw an `Error` with a message (not a TypeError from the glue, not a
// trap), and the instance must still work afterwards, its memory and reference table
// back near where they started.
import { readFileSync, readdirSync } from 'node:fs';
import { STYLES, tile } from './real-patterns.mjs';

/** mulberry32: small, fast, seeded. */
export function rng(seed) {
  let a = seed >>> 0;
  const next = () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
  const int = (n) => Math.floor(next() * n);
  return { next, int, pick: (list) => list[int(list.length)], chance: (p) => next() < p };
}

const fixture = (name) => new Uint8Array(readFileSync(new URL(`../fixtures/${name}`, import.meta.url)));
const wrap = (body, attrs = 'viewBox="0 0 100 100"') =>
  `<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" ${attrs}>${body}</svg>`;

const HANDMADE = [
  wrap('<defs><circle id="c" r="4" fill="#c33"/></defs><use href="#c" x="10" y="10"/><use xlink:href="#c" x="30" y="10"/>'),
  wrap('<style>.a{fill:#39c;stroke:#123;stroke-width:2}.b{fill:none;stroke:#c93}</style><rect class="a" x="5" y="5" width="20" height="20"/><path class="b" d="M40 40 A10 10 0 1 1 60 60 Q70 20 90 40 T95 80"/>'),
  wrap('<linearGradient id="g"><stop offset="0" stop-color="#f00"/><stop offset="1" stop-color="#00f"/></linearGradient><g transform="rotate(30 50 50) scale(1.5)"><ellipse cx="30" cy="30" rx="10" ry="5" fill="url(#g)"/><polygon points="10,80 30,60 50,80" stroke="#000"/></g>'),
  wrap('<path fill-rule="evenodd" d="M10 10h40v40h-40z M20 20h20v20h-20z" fill="#333"/><polyline points="60,10 70,30 80,10 90,30" fill="none" stroke="#0a0" stroke-width="3"/>'),
  wrap('<g opacity="0.5"><text x="10" y="20">hi</text><image href="data:image/png;base64,AAAA" width="4" height="4"/><line x1="0" y1="0" x2="100" y2="100" stroke="red"/></g>', 'width="120mm" height="80mm"'),
  '<?xml version="1.0"?><!DOCTYPE svg [<!ENTITY e "<rect width=\'3\' height=\'3\'/>">]>' + wrap('&e;<g transform="translate(10 10)">&e;</g>'),
];

/** The seed documents: the svg-patterns tiles (3x3), the hand-made ones, and the
 *  import's reference constructs (symbols, nested viewports, CSS, gradients, holes). */
export function svgSeeds() {
  const dir = new URL('../fixtures/svg/constructs/', import.meta.url);
  const constructs = readdirSync(dir).sort().map((f) => readFileSync(new URL(f, dir), 'utf8'));
  return [...Object.keys(STYLES).map((name) => tile(name, 30).svg), ...HANDMADE, ...constructs];
}

const HUGE = ['1e30', '-1e30', '1e308', '1e-300', 'NaN', 'Infinity', '-0', '99999999999', '0', '-5'];

/** One mutation of an SVG's text. */
function mutateSvg(r, s) {
  switch (r.int(12)) {
    case 0: { // flip characters
      const a = [...s];
      for (let k = 1 + r.int(8); k > 0; k--) a[r.int(a.length)] = String.fromCharCode(r.pick([60, 62, 34, 39, 38, 47, 61, 32, 48 + r.int(10), 97 + r.int(26), r.int(0x3000)]));
      return a.join('');
    }
    case 1: return s.slice(0, r.int(s.length)); // cut
    case 2: { // duplicate a slice
      const i = r.int(s.length), j = Math.min(s.length, i + r.int(400));
      return s.slice(0, j) + s.slice(i, j).repeat(1 + r.int(20)) + s.slice(j);
    }
    case 3: { // deep nesting
      const tag = r.pick(['g', 'a', 'svg', 'g transform="scale(10)"', 'g opacity="0.9"', 'clipPath id="k"', 'symbol', 'defs']);
      const name = tag.split(' ')[0];
      const n = r.pick([20, 80, 101, 150, 400, 2000]);
      const i = s.indexOf('>') + 1;
      return s.slice(0, i) + `<${tag}>`.repeat(n) + '<circle r="3"/>' + `</${name}>`.repeat(n) + s.slice(i);
    }
    case 4: // huge numbers
      return s.replace(/-?\d+(\.\d+)?/g, (m) => (r.chance(0.3) ? r.pick(HUGE) : m));
    case 5: { // reference chains and cycles
      const n = r.pick([5, 60, 99, 200]);
      const uses = Array.from({ length: n }, (_, k) => `<use id="u${k + 1}" href="#u${r.chance(0.05) ? r.int(n) : k}"/>`).join('');
      return s.replace('</svg>', `<defs><rect id="u0" width="2" height="2"/>${uses}</defs><use href="#u${n}"/></svg>`);
    }
    case 6: { // attributes
      const n = r.pick([10, 300, 3000, 9000]);
      const attrs = Array.from({ length: n }, (_, k) => ` data-x${k}="${k}"`).join('');
      return s.replace(/<(rect|path|circle|g)/, (m) => m + attrs);
    }
    case 7: { // style sheets
      const n = r.pick([10, 500, 2500]);
      const css = Array.from({ length: n }, (_, k) => `.q${k},#w${k} rect{fill:#${(k % 4096).toString(16).padStart(3, '0')}}`).join('');
      return s.replace('</svg>', `<style>${css}</style></svg>`);
    }
    case 9: { // descendant selector chains over deep nesting
      const depth = r.pick([10, 60, 99]);
      const rules = Array.from({ length: r.pick([1, 40, 400]) }, () => `${r.pick(['.nomatch ', '#none ', 'svg ', ''])}${'g '.repeat(1 + r.int(30))}${r.pick(['rect', 'circle', '*', 'g > rect', 'g + g rect', 'g ~ rect'])}{fill:#${r.int(4096).toString(16).padStart(3, '0')}}`).join('');
      const i = s.indexOf('>') + 1;
      return s.slice(0, i) + `<style>${rules}</style>` + '<g class="a">'.repeat(depth) + '<rect width="3" height="3"/>' + '</g>'.repeat(depth) + s.slice(i);
    }
    case 10: { // entity graphs: each entity refers to a few earlier ones
      const n = r.pick([3, 10, 30]);
      const decls = Array.from({ length: n }, (_, k) => {
        const refs = k === 0 ? 'x'.repeat(r.pick([1, 1000, 100000])) : Array.from({ length: 1 + r.int(12) }, () => `&e${r.int(k)};`).join('');
        return `<!ENTITY e${k} "${refs}">`;
      }).join('');
      const body = s.replace(/^<\?xml[^>]*>/, '');
      return `<?xml version="1.0"?><!DOCTYPE svg [${decls}]>` + body.replace('</svg>', `<text>${`&e${n - 1};`.repeat(1 + r.int(50))}</text><rect width="2" height="2" class="&e0;"/></svg>`);
    }
    case 11: { // huge declaration counts, in a style attribute or one rule
      const n = r.pick([1000, 20000, 300000]);
      const decls = 'fill:#123;stroke:red;'.repeat(n / 2);
      return r.chance(0.5) ? s.replace(/<(rect|path|circle)/, (m) => `${m} style="${decls}"`) : s.replace('</svg>', `<style>rect{${decls}}</style></svg>`);
    }
    default: { // transforms and geometry extremes
      const t = r.pick(['scale(1e15)', 'scale(0)', 'matrix(1e20 0 0 1e20 0 0)', 'rotate(NaN)', 'translate(1e30)', 'skewX(89.9999)', 'scale(-1e-30)']);
      return s.replace(/<(rect|path|circle|g|polygon|use)/, (m) => `<g transform="${t}">${m}`).replace('</svg>', '</g></svg>');
    }
  }
}

/** One mutation of image file bytes (keeps the signature sometimes, so decoders run). */
function mutateBytes(r, b) {
  const a = new Uint8Array(b);
  switch (r.int(5)) {
    case 0: for (let k = 1 + r.int(10); k > 0; k--) a[8 + r.int(a.length - 8)] = r.int(256); return a;
    case 1: return a.slice(0, r.int(a.length));
    case 2: { // PNG IHDR size / JPEG SOF size to something huge
      const out = new Uint8Array(a);
      const at = r.int(Math.min(40, out.length - 4));
      out.set([r.int(256), r.int(256), r.int(256), r.int(256)], at);
      return out;
    }
    case 3: { const i = r.int(a.length), j = Math.min(a.length, i + r.int(200)); return Uint8Array.from([...a.slice(0, j), ...a.slice(i, j), ...a.slice(i)]); }
    default: return Uint8Array.from({ length: r.int(64) }, () => r.int(256));
  }
}

const WEIRD = [undefined, null, NaN, Infinity, -Infinity, -1, 0, 1e300, -1e300, 1.5, 2 ** 53, '12', '', 'linear', true, [], {}, [1, 2], () => 1, Symbol.iterator];
function weird(r) { return r.pick(WEIRD); }
function number(r, lo, hi) { return r.chance(0.15) ? weird(r) : lo + r.int(hi - lo + 1); }

/** A random options object from known keys (and sometimes an unknown one). */
function options(r, keys, sized, extra = {}) {
  const o = { ...extra };
  for (const [k, gen] of Object.entries(keys)) if (r.chance(0.5)) o[k] = gen(r);
  if (sized) { o.width ??= number(r, 8, 96); o.height ??= number(r, 8, 96); }
  if (r.chance(0.05)) o[r.pick(['widht', 'colour', 'sead'])] = 1;
  if (r.chance(0.05)) return weird(r);
  return r.chance(0.1) ? hostile(r, o) : o;
}

/** `o` behind something that runs page code when read, or in a container that is not
 *  an options object. */
function hostile(r, o) {
  const boom = () => { throw new Error('page code threw'); };
  switch (r.int(7)) {
    case 0: return new Proxy(o, { get: boom });
    case 1: return new Proxy(o, { ownKeys: boom });
    case 2: return new Proxy(o, { getPrototypeOf: boom, has: boom });
    case 3: { const key = r.pick([...Object.keys(o), 'width', 'seed']); return Object.defineProperty({ ...o }, key, { get: boom, enumerable: true }); }
    case 4: return new Map(Object.entries(o));
    case 5: { const proto = { ...o }; return Object.create(proto); } // values on the prototype
    default: { const p = Proxy.revocable(o, {}); p.revoke(); return p.proxy; }
  }
}

/** A progress callback: none, one that throws, one that cancels, or one that calls the
 *  engine again (which must be refused, not run on the running call's stack). */
function progress(r, ps) {
  switch (r.int(8)) {
    case 0: return weird(r);
    case 1: return () => { throw new Error('progress threw'); };
    case 2: return (f) => f < 0.5;
    case 3: return () => { ps.parseSvg('<svg xmlns="http://www.w3.org/2000/svg"/>'); };
    case 4: { let n = 0; return () => { if (n++ < 2) try { ps.synthesizeStrokes([], { width: 1, height: 1 }); } catch { /* busy */ } }; }
    default: return undefined;
  }
}

/** A typed array whose buffer was transferred away, or one over shared memory. */
function oddBuffer(r, bytes) {
  if (r.chance(0.5)) {
    const copy = bytes.slice();
    structuredClone(copy.buffer, { transfer: [copy.buffer] });
    return r.chance(0.5) ? copy : copy.buffer;
  }
  const shared = new Uint8Array(new SharedArrayBuffer(bytes.length));
  shared.set(bytes);
  return shared;
}

const STROKE_OPTS = {
  pathTolerance: (r) => (r.chance(0.3) ? weird(r) : r.next() * 20), widthTolerance: (r) => r.next() * 5,
  colorTolerance: (r) => r.next() * 100, variation: (r) => r.chance(0.5), seed: (r) => number(r, 0, 1e6),
  support: (r) => (r.chance(0.3) ? weird(r) : r.next()), maxElements: (r) => number(r, 1, 5000), regularize: (r) => r.chance(0.5),
};
const TEX_OPTS = {
  seed: (r) => number(r, 0, 99), tileable: (r) => r.chance(0.5), levels: (r) => number(r, 0, 9), neighbourhood: (r) => number(r, 1, 11),
  exhaustive: (r) => r.chance(0.1),
};

function detachedFloats(r) {
  const f = new Float32Array(1 + r.int(64));
  structuredClone(f.buffer, { transfer: [f.buffer] });
  return f;
}

function image(r, w = 8 + r.int(40), h = 8 + r.int(40)) {
  const img = { width: w, height: h, data: Uint8ClampedArray.from({ length: w * h * 4 }, () => r.int(256)) };
  if (r.chance(0.1)) img.data = r.pick([new Uint8Array(3), null, 'pixels', new Float32Array(w * h * 4)]);
  else if (r.chance(0.05)) img.data = oddBuffer(r, new Uint8Array(img.data.buffer));
  if (r.chance(0.05)) img.width = weird(r);
  return img;
}

function strokes(r, ps, svgs) {
  if (r.chance(0.6)) {
    try { return ps.parseSvg(r.pick(svgs)).slice(0, 200); } catch { /* a mutated seed */ }
  }
  const list = Array.from({ length: r.int(30) }, () => {
    const x = r.int(200), y = r.int(200);
    const s = { points: [[x, y], [x + r.int(10), y + r.int(10)]], width: r.chance(0.1) ? weird(r) : 1 + r.int(4), stroke: r.pick(['#112233', '#aa0000', null, 'red', undefined]) };
    if (r.chance(0.1)) s.points = r.pick([[], [[NaN, 1]], 'xy', [[1e300, 1e300], [-1e300, 0]]]);
    if (r.chance(0.03)) return hostile(r, s);
    if (r.chance(0.02)) s.points = new Proxy([], { get: (t, k) => (k === 'length' ? r.pick([1e9, 3, -1, NaN]) : /^\d+$/.test(String(k)) ? [+k, 0] : Reflect.get(t, k)) });
    return s;
  });
  if (r.chance(0.02)) return new Proxy(list, { get: (t, k) => (k === 'length' ? r.pick([1e9, 2 ** 32, 7]) : Reflect.get(t, k)) });
  return list;
}

/** The calls the fuzzer makes: [name, (r, ps, seeds) => value]. */
export function cases(seeds) {
  const { svgs, images } = seeds;
  return [
    ['parseSvg', (r, ps) => ps.parseSvg(mutateSvg(r, r.pick(svgs)), options(r, { tolerance: (q) => (q.chance(0.5) ? weird(q) : q.next()), splitSubpaths: (q) => q.chance(0.5), maxPoints: (q) => number(q, 0, 1e6) }))],
    ['parseSvg', (r, ps) => ps.parseSvgReport(mutateSvg(r, mutateSvg(r, r.pick(svgs))))],
    ['parseSvg', (r, ps) => ps.parseSvg(r.chance(0.5) ? weird(r) : r.pick(svgs), r.chance(0.3) ? weird(r) : undefined)],
    ['synthesizeStrokes', (r, ps) => ps.synthesizeStrokes(r.chance(0.05) ? weird(r) : strokes(r, ps, svgs), options(r, STROKE_OPTS, true), r.chance(0.2) ? progress(r, ps) : undefined).strokes.length],
    ['strokeTile', (r, ps) => ps.strokeTile(strokes(r, ps, svgs), options(r, { repeats: (q) => number(q, 0, 9), seed: (q) => number(q, 0, 9), variation: (q) => q.chance(0.5) }, false)).strokes.length],
    ['suggestStrokes', (r, ps) => ps.suggestStrokes(strokes(r, ps, svgs), options(r, { count: (q) => number(q, 0, 80), fill: (q) => q.chance(0.5), region: (q) => (q.chance(0.7) ? [number(q, -50, 50), number(q, -50, 50), number(q, -10, 2000), number(q, -10, 2000)] : weird(q)), seed: (q) => number(q, 0, 9) }, false)).strokes.length],
    ['classifyStrokes', (r, ps) => ps.classifyStrokes(strokes(r, ps, svgs), options(r, STROKE_OPTS, false)).count],
    ['decodeImage', (r, ps) => ps.decodeImage(r.chance(0.85) ? mutateBytes(r, r.pick(images)) : r.chance(0.5) ? oddBuffer(r, r.pick(images)) : weird(r))],
    ['encodePng', (r, ps) => ps.encodePng(image(r)).length],
    ['synthesizeTexture', (r, ps) => ps.synthesizeTexture(image(r), options(r, TEX_OPTS, true), r.chance(0.2) ? progress(r, ps) : undefined).width],
    ['blendTextures', (r, ps) => ps.blendTextures(image(r), image(r), options(r, TEX_OPTS, true, { coefficient: r.pick(['linear', 'ease', 'radial', 'steep', 'wobbly', new Float32Array(r.int(20)), undefined, 7, detachedFloats(r)]), angle: r.chance(0.3) ? weird(r) : undefined })).width],
    ['seamlessTile', (r, ps) => ps.seamlessTile(image(r), options(r, { method: (q) => q.pick(['etfmcm', 'tfmcm', 'synthesis', 'magic']), size: (q) => q.pick([8, 16, 32, 12, 1024, -8]), seed: (q) => number(q, 0, 9), maxCountDifference: (q) => number(q, -5, 300) }, false)).seamScore],
  ];
}

export function loadSeeds() {
  return {
    svgs: svgSeeds(),
    images: ['fuzz/brick.jpg', 'fuzz/brick-progressive.jpg', 'fuzz/grass-grey.png', 'fuzz/wood-rgba.png'].map(fixture),
  };
}

/**
 * Runs `iterations` seeded cases against the package `ps`. Returns counts by outcome
 * (ok, error, trap, foreign: a non-Error or glue TypeError), the slowest case and the
 * failures (with their seeds, to replay).
 */
export function fuzz(ps, { seed = 1, iterations = 1000, slowMs = 10_000 } = {}) {
  const seeds = loadSeeds();
  const all = cases(seeds);
  const counts = { ok: 0, error: 0, trap: 0, foreign: 0, broken: 0, slow: 0 };
  const failures = [];
  let slowest = { ms: 0 };
  const check = [{ points: [[0, 0], [4, 4]], width: 1, stroke: '#000000' }, { points: [[20, 0], [24, 4]], width: 1, stroke: '#000000' }];
  for (let i = 0; i < iterations; i++) {
    const caseSeed = seed * 1_000_003 + i;
    const r = rng(caseSeed);
    const [name, run] = r.pick(all);
    const t0 = performance.now();
    let outcome;
    try {
      run(r, ps);
      outcome = 'ok';
    } catch (e) {
      if (e instanceof WebAssembly.RuntimeError || e?.name === 'InternalError') outcome = 'trap';
      else if (e instanceof Error && !(e instanceof TypeError) && e.message.length > 8) outcome = 'error';
      else outcome = 'foreign';
      if (outcome !== 'error') failures.push({ caseSeed, name, outcome, message: String(e?.message ?? e).slice(0, 200) });
    }
    const ms = performance.now() - t0;
    counts[outcome]++;
    if (ms > slowest.ms) slowest = { ms, name, caseSeed };
    if (ms > slowMs) { counts.slow++; failures.push({ caseSeed, name, outcome: 'slow', message: `${Math.round(ms)} ms` }); }
    try {
      if (ps.synthesizeStrokes(check, { width: 60, height: 10, seed: 1 }).strokes.length < 2) throw new Error('no strokes');
      const d = ps.diagnostics?.();
      if (d && d.memoryBytes > d.baselineBytes + (64 << 20)) throw new Error(`memory kept: ${d.memoryBytes >> 20} MB`);
      if (d && d.references > d.baselineReferences + 1024 + 128) throw new Error(`references kept: ${d.references}`);
    } catch (e) {
      counts.broken++;
      failures.push({ caseSeed, name, outcome: 'broken instance', message: String(e?.message ?? e).slice(0, 200) });
    }
  }
  return { counts, slowest, failures };
}
