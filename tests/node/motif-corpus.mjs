// Multi-part motifs from real npm content, each laid 3x3 on a lattice as the example and
// 10x10 periods asked for; the output must be the example's periodic extension with every
// part of a motif in its own place (no part put where another part belongs).
// - lucide-static (ISC): stroke icons of 4-8 separate paths/circles/rects (some parts
//   touch, some stand apart: paw pads, rain drops), on square, hexagonal, brick, oblique
//   and rotated (lattice and icon turned 30 degrees) lattices, and two icons alternating;
// - @twemoji/svg (MIT package; the Twemoji graphics are CC-BY 4.0): emoji of 5-11 filled
//   parts in 3-7 colours, on square and hexagonal lattices;
// - the Hershey "futural" single-stroke font (public domain; tests/fixtures/hershey, from the
//   hersheytext package, MIT): letters of
//   2-4 strokes and two words, on a square lattice (40 units), every copy wobbled by its
//   own smooth noise (polylines cut to 1.5-unit steps; points moved 0.65 units RMS, 1.6%
//   of the spacing, at most 1.5; seeded), as if drawn by hand, and two exact controls;
// - four of those icons and two emoji placed by hand: each copy turned up to 2 degrees
//   and moved up to 0.6 units (seeded), so no exact period exists and the motif model has
//   to find the copies.
// `measure` compares the output with the ideal extension (corpus.mjs's approach, on the
// example's least-squares lattice, up to one global translation) and counts `wrong`.
import { readFileSync } from 'node:fs';

const nm = (path) => readFileSync(new URL(`../../node_modules/${path}`, import.meta.url), 'utf8');
const r2 = (v) => Math.round(v * 100) / 100;

/**
 * Nine copies at p0 + i a + j b (document order j, then i); `copy(x, y, i, j)` returns
 * a copy's markup. The SVG fits them with `size` (a copy's extent) and a margin.
 */
function lay(a, b, size, copy) {
  const at = [];
  for (let j = 0; j < 3; j++) for (let i = 0; i < 3; i++) at.push([i, j, i * a[0] + j * b[0], i * a[1] + j * b[1]]);
  const [x0, y0, m] = [Math.min(...at.map((p) => p[2])), Math.min(...at.map((p) => p[3])), 12];
  const body = at.map(([i, j, x, y]) => copy(r2(x - x0 + m), r2(y - y0 + m), i, j)).join('');
  const W = Math.max(...at.map((p) => p[2])) - x0 + size + 2 * m, H = Math.max(...at.map((p) => p[3])) - y0 + size + 2 * m;
  return `<svg xmlns="http://www.w3.org/2000/svg" width="${r2(W)}" height="${r2(H)}">${body}</svg>`;
}

const rot = ([x, y], deg, t = (deg * Math.PI) / 180) => [r2(x * Math.cos(t) - y * Math.sin(t)), r2(x * Math.sin(t) + y * Math.cos(t))];

export const LUCIDE = ['paw-print', 'cloud-rain', 'calendar', 'bike', 'fish', 'drama'];
const lucideInner = (name) => nm(`lucide-static/icons/${name}.svg`).replace(/<!--[\s\S]*?-->/g, '').replace(/^\s*<svg[^>]*>/, '').replace(/<\/svg>\s*$/, '').replace(/\s+/g, ' ').trim();
const lucideCopy = (inner, colour, x, y, turn = 0) =>
  `<g transform="translate(${x} ${y})${turn ? ` rotate(${turn} 12 12)` : ''}" fill="none" stroke="${colour}" stroke-width="2" stroke-linecap="round" stroke-linejoin="round">${inner}</g>`;

function lucide() {
  // Period vectors and the icon's turn: square, hexagonal, brick, oblique, and the
  // square lattice with the icon turned 30 degrees.
  const LATTICES = { square: [[32, 0], [0, 32], 0], hexagonal: [[32, 0], [16, 28], 0], brick: [[40, 0], [20, 30], 0],
    oblique: [[34, 0], [10, 30], 0], rotated30: [rot([32, 0], 30), rot([0, 32], 30), 30] };
  const cases = [];
  for (const icon of LUCIDE) {
    const inner = lucideInner(icon);
    for (const [lattice, [a, b, turn]] of Object.entries(LATTICES)) {
      cases.push({ corpus: 'lucide', name: `${icon}/${lattice}`, a, b, svg: lay(a, b, 24, (x, y) => lucideCopy(inner, '#2a4d69', x, y, turn)) });
    }
  }
  // Two icons alternating along rows: the period holds both, in two colours.
  for (let k = 0; k + 1 < LUCIDE.length; k += 2) {
    const [p, q] = [lucideInner(LUCIDE[k]), lucideInner(LUCIDE[k + 1])];
    const [a, b] = [[64, 0], [0, 32]];
    const svg = lay(a, b, 56, (x, y) => lucideCopy(p, '#aa3322', x, y) + lucideCopy(q, '#2255aa', x + 32, y));
    cases.push({ corpus: 'lucide', name: `${LUCIDE[k]}+${LUCIDE[k + 1]}/two-icons`, a, b, svg });
  }
  return cases;
}

// Grinning face, rainbow, turtle, house, game die, frog.
export const TWEMOJI = ['1f600', '1f308', '1f422', '1f3e0', '1f3b2', '1f438'];
const emojiInner = (code) => nm(`@twemoji/svg/${code}.svg`).replace(/^\s*<svg[^>]*>/, '').replace(/<\/svg>\s*$/, '');

function twemoji() {
  const LATTICES = { square: [[44, 0], [0, 44]], hexagonal: [[44, 0], [22, 38]] };
  const cases = [];
  for (const code of TWEMOJI) {
    const inner = emojiInner(code);
    for (const [lattice, [a, b]] of Object.entries(LATTICES)) {
      cases.push({ corpus: 'twemoji', name: `${code}/${lattice}`, a, b, svg: lay(a, b, 36, (x, y) => `<g transform="translate(${x} ${y})">${inner}</g>`) });
    }
  }
  return cases;
}

/** Mulberry32: a small seeded generator, so every run lays the same wobble. */
function rng(seed) {
  let s = seed >>> 0;
  return () => {
    let t = (s = (s + 0x6d2b79f5) >>> 0);
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/**
 * A smooth displacement field of about `amp` (three plane waves per axis, wavelengths
 * 12-28 units, random directions and phases): a function of the glyph's own coordinates,
 * so strokes that meet still meet.
 */
function wobble(random, amp) {
  const waves = [0, 1].map(() => Array.from({ length: 3 }, () => {
    const th = random() * 2 * Math.PI, k = (2 * Math.PI) / (12 + 16 * random());
    return [k * Math.cos(th), k * Math.sin(th), random() * 2 * Math.PI];
  }));
  const f = (ws, x, y) => (amp / Math.sqrt(1.5)) * ws.reduce((s, [kx, ky, ph]) => s + Math.sin(kx * x + ky * y + ph), 0) / Math.sqrt(3);
  return (x, y) => [x + f(waves[0], x, y), y + f(waves[1], x, y)];
}

/** A Hershey glyph run's strokes: polylines in font units, the text starting at x = 0. */
function hershey(text) {
  const chars = JSON.parse(readFileSync(new URL('../fixtures/hershey/futural.json', import.meta.url), 'utf8')).chars;
  const lines = [];
  let pen = 0;
  for (const ch of text) {
    const g = chars[ch.charCodeAt(0) - 33];
    for (const sub of g.d.split('M').filter((s) => s.trim())) {
      lines.push(sub.replace('L', ' ').trim().split(/\s+/).map((p) => p.split(',').map(Number)).map(([x, y]) => [x + pen, y]));
    }
    pen += 2 * g.o;
  }
  return { lines, width: pen };
}

/** Segments cut to steps of at most `step` units, so a wobble bends them. */
const densify = (line, step = 1.5) => line.flatMap((p, n) => {
  if (n === 0) return [p];
  const q = line[n - 1], k = Math.ceil(Math.hypot(p[0] - q[0], p[1] - q[1]) / step);
  return Array.from({ length: k }, (_, t) => [q[0] + ((p[0] - q[0]) * (t + 1)) / k, q[1] + ((p[1] - q[1]) * (t + 1)) / k]);
});

export const HERSHEY = ['A', 'E', 'H', 'K', 'X', '#', 'B', 'TEXT', 'KEY'];

function hersheyCases() {
  const cases = [];
  const one = (text, wobbled, seed) => {
    const { lines, width } = hershey(text);
    const a = [Math.max(40, Math.ceil(width + 12)), 0], b = [0, 40];
    const random = rng(seed);
    const amp = 0.02 * Math.min(a[0], b[1]);
    const svg = lay(a, b, Math.max(width, 32), (x, y) => {
      const warp = wobbled ? wobble(random, amp) : (px, py) => [px, py];
      return lines.map((l) => `<path d="M${densify(l).map((p) => warp(...p)).map(([px, py]) => `${r2(px + x)} ${r2(py + 4 + y)}`).join(' L')}" fill="none" stroke="#202020" stroke-width="1.2" stroke-linecap="round"/>`).join('');
    });
    cases.push({ corpus: 'hershey', name: `${text}/${wobbled ? 'wobbled' : 'exact'}`, a, b, svg, handmade: wobbled });
  };
  HERSHEY.forEach((t, n) => one(t, true, 1000 + n));
  one('A', false, 0);
  one('TEXT', false, 0);
  return cases;
}

/**
 * Icons and emoji placed by hand: each copy turned up to 2 degrees about its centre and
 * moved up to 0.6 units (seeded), so the repeat is no exact tile and the motif model,
 * not the exact period search, has to find the copies.
 */
function placedByHand() {
  const [a, b] = [[40, 0], [0, 40]];
  const jitter = (random, x, y, size) => `translate(${r2(x + 1.2 * random() - 0.6)} ${r2(y + 1.2 * random() - 0.6)}) rotate(${r2(4 * random() - 2)} ${size / 2} ${size / 2})`;
  const icons = ['paw-print', 'cloud-rain', 'bike', 'drama'].map((icon, n) => {
    const inner = lucideInner(icon), random = rng(2000 + n);
    const svg = lay(a, b, 24, (x, y) => lucideCopy(inner, '#2a4d69', x, y).replace(/transform="[^"]*"/, `transform="${jitter(random, x, y, 24)}"`));
    return { corpus: 'lucide', name: `${icon}/by-hand`, a, b, svg, handmade: true };
  });
  const emoji = ['1f600', '1f3e0'].map((code, n) => {
    const [inner, random, p, q] = [emojiInner(code), rng(3000 + n), [48, 0], [0, 48]];
    return { corpus: 'twemoji', name: `${code}/by-hand`, a: p, b: q, svg: lay(p, q, 36, (x, y) => `<g transform="${jitter(random, x, y, 36)}">${inner}</g>`), handmade: true };
  });
  return [...icons, ...emoji];
}

export function cases() {
  return [...lucide(), ...twemoji(), ...hersheyCases(), ...placedByHand()];
}

const box = (s) => {
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (const [x, y] of s.points) { x0 = Math.min(x0, x); y0 = Math.min(y0, y); x1 = Math.max(x1, x); y1 = Math.max(y1, y); }
  return { c: [(x0 + x1) / 2, (y0 + y1) / 2], size: [x1 - x0, y1 - y0] };
};

/** A stroke's points less its box centre. */
const centred = (s, { c } = box(s)) => s.points.map(([x, y]) => [x - c[0], y - c[1]]);

/**
 * Two centred drawings alike: point by point (either direction) within `eps`, or, with
 * different point counts, every point within `eps` of the other drawing.
 */
function like(p, q, eps) {
  const close = (u, v) => Math.hypot(u[0] - v[0], u[1] - v[1]) <= eps;
  if (p.length === q.length) return p.every((u, n) => close(u, q[n])) || p.every((u, n) => close(u, q[q.length - 1 - n]));
  const within = (s, t) => s.every((u) => t.some((v) => close(u, v)));
  return within(p, q) && within(q, p);
}

/**
 * The translation (less than a period) that most output strokes share from the sites of
 * their class's parts, from a sample of up to 256 strokes: the mean of the largest
 * cluster (radius tol / 2) of residuals reduced to the lattice's cell; none (0, 0) when
 * no translation gathers clearly more (a tenth more) than none.
 */
function align(out, parts, frame, a, b, tol) {
  const det = a[0] * b[1] - a[1] * b[0];
  const step = Math.max(1, Math.floor(out.strokes.length / 256));
  const res = [];
  for (let n = 0; n < out.strokes.length; n += step) {
    const { c } = box(out.strokes[n]);
    for (const part of parts) {
      if (part.c !== out.classes[n]) continue;
      const d = [c[0] - part.p[0] - frame[0], c[1] - part.p[1] - frame[1]];
      let u = (d[0] * b[1] - d[1] * b[0]) / det, v = (a[0] * d[1] - a[1] * d[0]) / det;
      [u, v] = [u - Math.round(u), v - Math.round(v)];
      res.push([u * a[0] + v * b[0], u * a[1] + v * b[1]]);
    }
  }
  const around = (t) => res.filter((r) => Math.hypot(r[0] - t[0], r[1] - t[1]) < tol / 2);
  let best = [0, 0], most = around(best).length * 1.1;
  for (const r of res) {
    const n = around(r).length;
    if (n > most) [best, most] = [r, n];
  }
  const near = around(best);
  return near.length ? [0, 1].map((d) => near.reduce((s, r) => s + r[d], 0) / near.length) : [0, 0];
}

/**
 * Synthesizes 10x10 periods from the case's example with the package `ps` and options,
 * and compares with the ideal periodic extension: recall of the ideal sites whose drawing
 * reaches into the output, strays (no site of its class within 5% of a period), stacked
 * duplicates, drift (95th percentile residual over the shorter period), `wrong` (share of
 * output strokes not their site's part: bounding-box size outside the spread of the
 * part's nine copies by more than half a unit, other colours, a drawing that is none of
 * those copies, or a drawing that is not the part of the place `sources` names;
 * `dressed` counts the last alone), offset (of the whole output from the centred frame,
 * over the period), split (parts whose copies got more than one class) and time.
 */
export function measure(ps, c, options = {}) {
  const strokes = ps.parseSvg(c.svg);
  const perCopy = strokes.length / 9;
  if (!Number.isInteger(perCopy)) throw new Error(`${c.name}: ${strokes.length} strokes in a 3x3 repeat`);
  const w = 10 * Math.abs(c.a[0]) + 10 * Math.abs(c.b[0]), h = 10 * Math.abs(c.a[1]) + 10 * Math.abs(c.b[1]);
  const t0 = performance.now();
  const out = ps.synthesizeStrokes(strokes, { width: w, height: h, seed: 1, ...options });
  const ms = performance.now() - t0;
  const cls = out.classification.classes;
  const boxes = strokes.map(box);
  // The example's own lattice: the least-squares periods of its nine copies (copy n at
  // i = n % 3, j = n / 3; a balanced design, so each period is a contrast of the means).
  // For an exact repeat it is the case's lattice; for a hand-made one, what the example
  // shows (3x3 jittered copies leave the drawn lattice a few tenths of a unit off).
  const contrast = (f) => [0, 1].map((d) => strokes.reduce((s, st, q) => s + f(Math.floor(q / perCopy)) * boxes[q].c[d], 0) / (6 * perCopy));
  const [a, b] = [contrast((n) => (n % 3) - 1), contrast((n) => Math.floor(n / 3) - 1)];
  // Each part k: its place (the mean over its nine copies, less their lattice offsets),
  // the spread of its drawn size, its paint and class.
  const parts = Array.from({ length: perCopy }, (_, k) => {
    const copies = Array.from({ length: 9 }, (_, n) => ({ s: k + n * perCopy, i: n % 3, j: Math.floor(n / 3) }));
    const p = [0, 1].map((d) => copies.reduce((s, { s: q, i, j }) => s + boxes[q].c[d] - i * a[d] - j * b[d], 0) / 9);
    const lo = [0, 1].map((d) => Math.min(...copies.map(({ s: q }) => boxes[q].size[d])));
    const hi = [0, 1].map((d) => Math.max(...copies.map(({ s: q }) => boxes[q].size[d])));
    const pad = strokes[k].stroke ? strokes[k].width / 2 : 0, drawn = copies.map(({ s: q }) => centred(strokes[q]));
    const split = new Set(copies.map(({ s: q }) => cls[q])).size > 1;
    return { p, lo, hi, drawn, half: [hi[0] / 2 + pad, hi[1] / 2 + pad], c: cls[k], split, stroke: strokes[k].stroke ?? '', fill: strokes[k].fill ?? '' };
  });
  const cs = boxes.map((x) => x.c);
  const period = Math.min(Math.hypot(...a), Math.hypot(...b));
  const tol = 0.05 * period;
  // The example centred in the area (corpus.mjs's frame), then moved by the one global
  // translation that puts most output strokes on their class's parts: where the frame
  // sits is no part of the pattern (`offset` reports it).
  const frame = [0, 1].map((d) => [w, h][d] / 2 - (Math.min(...cs.map((p) => p[d])) + Math.max(...cs.map((p) => p[d]))) / 2);
  const offset = align(out, parts, frame, a, b, tol);
  const shift = [frame[0] + offset[0], frame[1] + offset[1]];
  const reaches = (p, k, m) => p[0] + parts[k].half[0] > m && p[0] - parts[k].half[0] < w - m && p[1] + parts[k].half[1] > m && p[1] - parts[k].half[1] < h - m;
  // Ideal sites, one per part and lattice point, in a hash by cell of `tol`.
  const [hash, sites, range] = [new Map(), [], 16];
  const key = (x, y) => `${Math.floor(x / tol)},${Math.floor(y / tol)}`;
  parts.forEach((part, k) => {
    for (let i = -range; i <= range; i++) for (let j = -range; j <= range; j++) {
      const p = [part.p[0] + shift[0] + i * a[0] + j * b[0], part.p[1] + shift[1] + i * a[1] + j * b[1]];
      if (!reaches(p, k, -tol)) continue;
      const site = { p, k, c: part.c, hits: 0, inside: reaches(p, k, tol) };
      sites.push(site);
      (hash.get(key(...p)) ?? hash.set(key(...p), []).get(key(...p))).push(site);
    }
  });
  const near = (x, y, c, f) => {
    const [cx, cy] = [Math.floor(x / tol), Math.floor(y / tol)];
    for (let dy = -1; dy <= 1; dy++) for (let dx = -1; dx <= 1; dx++) for (const s of hash.get(`${cx + dx},${cy + dy}`) ?? []) if (s.c === c) f(s);
  };
  let [stray, wrong, dressed] = [0, 0, 0];
  const residuals = [];
  // A right part: its size within its copies' spread (half a unit of slack), its paint,
  // and its drawing one of its copies' (so a mirrored stroke of the same box is wrong).
  const slack = 0.5;
  const right = (s, size, drawing, part) => [0, 1].every((d) => size[d] >= part.lo[d] - slack && size[d] <= part.hi[d] + slack)
    && (s.stroke ?? '') === part.stroke && (s.fill ?? '') === part.fill && part.drawn.some((q) => like(drawing, q, slack));
  out.strokes.forEach((s, idx) => {
    const { c: [x, y], size } = box(s);
    const drawing = centred(s);
    // The nearest site of its class within the tolerance, preferring sites whose part
    // it is (two parts of one class can share a centre: the strokes of an X).
    let best = null, bd = Infinity, ok = false;
    near(x, y, out.classes[idx], (site) => {
      const d = Math.hypot(site.p[0] - x, site.p[1] - y);
      if (d >= tol) return;
      const fit = right(s, size, drawing, parts[site.k]);
      if ((fit && !ok) || (fit === ok && d < bd)) [best, bd, ok] = [site, d, fit];
    });
    // Its drawing must also be a copy of the part whose place it claims (`sources`; the
    // copies are laid part by part in one order): variation dresses a place with a copy
    // of that same place, never with another part.
    const own = parts[out.sources[idx] % perCopy].drawn.some((q) => like(drawing, q, slack));
    if (!own) dressed++;
    if (!best) { stray++; return; }
    best.hits++;
    residuals.push(bd / period);
    if (!ok || !own) wrong++;
  });
  residuals.sort((p, q) => p - q);
  const inner = sites.filter((s) => s.inside);
  const covered = inner.filter((s) => s.hits > 0).length;
  return {
    corpus: c.corpus, name: c.name, a: c.a, b: c.b, fitted: [a, b], example: strokes.length, parts: perCopy, out: out.strokes.length, sites: inner.length,
    recall: covered / inner.length, stray, stacked: sites.reduce((n, s) => n + Math.max(0, s.hits - 1), 0),
    offset: Math.hypot(...offset) / period, wrong: out.strokes.length ? wrong / out.strokes.length : 0, wrongCount: wrong, dressed, split: parts.filter((p) => p.split).length,
    kinds: out.classification.kinds, classes: out.classification.count, drift: residuals[Math.floor(0.95 * (residuals.length - 1))] ?? 0, ms,
  };
}
