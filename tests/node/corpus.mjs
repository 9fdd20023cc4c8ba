// The real-pattern corpus of issue 7: openly licensed repeating SVG content as a person
// would import it, a 3x3 repeat of one period as the example, 10x10 periods asked for.
// - svg-patterns (ISC): its tiles;
// - geopattern (MIT): every generator at two seeds (full backgrounds: rects of 100%,
//   shapes that overflow the tile and are drawn again on the far side);
// - simple-icons (CC0-1.0): icons with holes (letters with counters, rings, cut-outs)
//   laid out on square, hexagonal and brick lattices, and two icons alternating;
// - hero-patterns (MIT; Steve Schoger's heropatterns.com tiles): every tile, many with
//   shapes cut at the tile's edge that abut in the repeat, compound paths with holes,
//   long line work (graph paper, circuit boards) and motifs of hundreds of pieces.
// `measure` compares the output with the example's exact periodic extension.
import { createRequire } from 'node:module';
import { readFileSync } from 'node:fs';
import { STYLES, tile } from './real-patterns.mjs';

const require = createRequire(import.meta.url);

/** One period copy at lattice offset (i, j), as SVG markup. */
const repeat3 = (copy) => {
  let body = '';
  for (let j = 0; j < 3; j++) for (let i = 0; i < 3; i++) body += copy(i, j);
  return body;
};

function svgPatterns() {
  return Object.keys(STYLES).map((name) => {
    const { svg, px, py } = tile(name);
    return { corpus: 'svg-patterns', name, svg, a: [px, 0], b: [0, py] };
  });
}

export const GEOPATTERN = ['octogons', 'overlappingCircles', 'plusSigns', 'xes', 'sineWaves', 'hexagons', 'overlappingRings',
  'plaid', 'triangles', 'squares', 'concentricCircles', 'diamonds', 'tessellation', 'nestedSquares', 'mosaicSquares', 'chevrons'];

function geopattern(seeds = ['patternsynth', 'repeat']) {
  const GeoPattern = require('geopattern');
  return GEOPATTERN.flatMap((generator) => seeds.map((seed) => {
    const src = GeoPattern.generate(seed, { generator }).toString();
    const [, w, h] = src.match(/<svg[^>]*width="([\d.]+)"[^>]*height="([\d.]+)"/);
    const inner = src.replace(/^<svg[^>]*>/, '').replace(/<\/svg>\s*$/, '');
    const [W, H] = [Number(w), Number(h)];
    // Each copy its own viewport, so "100%" means the tile, as in a CSS background.
    const body = repeat3((i, j) => `<svg x="${i * W}" y="${j * H}" width="${W}" height="${H}" overflow="visible">${inner}</svg>`);
    return { corpus: 'geopattern', name: `${generator}/${seed}`, svg: `<svg xmlns="http://www.w3.org/2000/svg" width="${3 * W}" height="${3 * H}">${body}</svg>`, a: [W, 0], b: [0, H] };
  }));
}

export const ICONS = ['airbyte', 'bitly', 'ifttt', 'gumroad', 'qwant', 'pnpm'];

function simpleIcons() {
  const path = (name) => readFileSync(new URL(`../../node_modules/simple-icons/icons/${name}.svg`, import.meta.url), 'utf8').match(/<path d="([^"]+)"/)[1];
  const LATTICES = {
    square: [[32, 0], [0, 32]],
    hexagonal: [[32, 0], [16, 28]],
    brick: [[40, 0], [20, 30]],
  };
  const cases = [];
  ICONS.forEach((icon, n) => {
    const d = path(icon);
    for (const [lattice, [a, b]] of Object.entries(LATTICES)) {
      const body = repeat3((i, j) => `<path transform="translate(${i * a[0] + j * b[0]} ${i * a[1] + j * b[1]})" d="${d}" fill="#${(0x305070 + n * 0x1f2b3c).toString(16).slice(-6)}"/>`);
      const W = 3 * a[0] + 3 * b[0] + 24, H = 3 * a[1] + 3 * b[1] + 24;
      cases.push({ corpus: 'simple-icons', name: `${icon}/${lattice}`, svg: `<svg xmlns="http://www.w3.org/2000/svg" width="${W}" height="${H}">${body}</svg>`, a, b });
    }
  });
  // Two classes: two icons alternating along rows (the period holds both).
  for (let k = 0; k + 1 < ICONS.length; k += 2) {
    const [d0, d1] = [path(ICONS[k]), path(ICONS[k + 1])];
    const body = repeat3((i, j) => `<g transform="translate(${i * 64} ${j * 32})"><path d="${d0}" fill="#aa3322"/><path transform="translate(32 0)" d="${d1}" fill="#2255aa"/></g>`);
    cases.push({ corpus: 'simple-icons', name: `${ICONS[k]}+${ICONS[k + 1]}/two-classes`, svg: `<svg xmlns="http://www.w3.org/2000/svg" width="${3 * 64}" height="${3 * 32}">${body}</svg>`, a: [64, 0], b: [0, 32] });
  }
  return cases;
}

/** Every hero-patterns tile, in one colour, as the page would import it. */
function heroPatterns() {
  const hero = require('hero-patterns');
  return Object.keys(hero).sort().map((name) => {
    const src = decodeURIComponent(hero[name]('#203040', 1).replace(/^url\('data:image\/svg\+xml,/, '').replace(/'\)$/, ''));
    const root = src.match(/^<svg[^>]*>/)[0];
    const [W, H] = ['width', 'height'].map((k) => Number(root.match(new RegExp(`\\s${k}="([\\d.]+)"`))[1]));
    const viewBox = root.match(/viewBox="([^"]+)"/)?.[1] ?? `0 0 ${W} ${H}`;
    const inner = src.replace(/^<svg[^>]*>/, '').replace(/<\/svg>\s*$/, '');
    const body = repeat3((i, j) => `<svg x="${i * W}" y="${j * H}" width="${W}" height="${H}" viewBox="${viewBox}" overflow="visible">${inner}</svg>`);
    return { corpus: 'hero-patterns', name, svg: `<svg xmlns="http://www.w3.org/2000/svg" width="${3 * W}" height="${3 * H}">${body}</svg>`, a: [W, 0], b: [0, H] };
  });
}

export function corpus() {
  return [...svgPatterns(), ...geopattern(), ...simpleIcons(), ...heroPatterns()];
}

const centre = (s) => {
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (const [x, y] of s.points) { x0 = Math.min(x0, x); y0 = Math.min(y0, y); x1 = Math.max(x1, x); y1 = Math.max(y1, y); }
  return [(x0 + x1) / 2, (y0 + y1) / 2];
};

/**
 * Synthesizes 10x10 periods from the case's example with the package `ps` and compares
 * with the exact periodic extension: recall of the ideal sites whose drawing reaches
 * into the output (so the output is covered to its edges), strays (an
 * element on no site of its class), stacked duplicates, drift (95th percentile residual
 * over the shorter period), time.
 */
export function measure(ps, c, options = { variation: false }) {
  const strokes = ps.parseSvg(c.svg);
  const perCopy = strokes.length / 9;
  if (!Number.isInteger(perCopy)) throw new Error(`${c.name}: ${strokes.length} strokes in a 3x3 repeat`);
  const [a, b] = [c.a, c.b];
  const w = 10 * Math.abs(a[0]) + 10 * Math.abs(b[0]), h = 10 * Math.abs(a[1]) + 10 * Math.abs(b[1]);
  const t0 = performance.now();
  const out = ps.synthesizeStrokes(strokes, { width: w, height: h, seed: 1, ...options });
  const ms = performance.now() - t0;
  const cls = out.classification.classes;
  const refs = strokes.map(centre);
  // Half the drawn size of each element: a site is in the output when its drawing
  // reaches into the area (the SVG's viewport clips the rest).
  const half = strokes.map((st) => {
    const xs = st.points.map((q) => q[0]), ys = st.points.map((q) => q[1]);
    const pad = st.stroke ? st.width / 2 : 0;
    return [(Math.max(...xs) - Math.min(...xs)) / 2 + pad, (Math.max(...ys) - Math.min(...ys)) / 2 + pad];
  });
  // Overlap of a drawing centred at p with the area, by more than `m`.
  const reaches = (p, k, m) => p[0] + half[k][0] > m && p[0] - half[k][0] < w - m && p[1] + half[k][1] > m && p[1] - half[k][1] < h - m;
  const xs = refs.map((p) => p[0]), ys = refs.map((p) => p[1]);
  const shift = [w / 2 - (Math.min(...xs) + Math.max(...xs)) / 2, h / 2 - (Math.min(...ys) + Math.max(...ys)) / 2];
  const period = Math.min(Math.hypot(...a), Math.hypot(...b));
  const tol = 0.05 * period;
  // Ideal sites, in a hash by cell of `tol`; one site per class where copies overlap:
  // a shape drawn again on the far side of its tile lands near a neighbour copy's own
  // (geopattern rounds the tile size, so only near). Two shapes of one copy close
  // together (plaid's stripes) stay two sites.
  const same = Math.min(0.5, 0.01 * period);
  const cell = (x, y) => `${Math.floor(x / tol)},${Math.floor(y / tol)}`;
  const hash = new Map();
  const near = (x, y, cls, f) => {
    const [cx, cy] = [Math.floor(x / tol), Math.floor(y / tol)];
    for (let dy = -1; dy <= 1; dy++) for (let dx = -1; dx <= 1; dx++) for (const s of hash.get(`${cx + dx},${cy + dy}`) ?? []) if (s.c === cls) f(s);
  };
  const sites = [];
  const range = 16;
  for (let k = 0; k < perCopy; k++) {
    for (let i = -range; i <= range; i++) for (let j = -range; j <= range; j++) {
      const p = [refs[k][0] + shift[0] + i * a[0] + j * b[0], refs[k][1] + shift[1] + i * a[1] + j * b[1]];
      if (!reaches(p, k, -tol)) continue;
      let dup = false;
      near(p[0], p[1], cls[k], (s) => {
        const d = Math.hypot(s.p[0] - p[0], s.p[1] - p[1]);
        // The same drawing (its size too): two halves of a shape cut at the tile's edge
        // are two sites, though near and alike enough to share a class.
        const alike = Math.abs(half[s.k][0] - half[k][0]) < 0.5 && Math.abs(half[s.k][1] - half[k][1]) < 0.5;
        dup ||= d < same || (alike && d < 0.02 * period && (s.i !== i || s.j !== j));
      });
      if (dup) continue;
      const site = { p, c: cls[k], k, hits: 0, i, j, inside: reaches(p, k, tol) };
      sites.push(site);
      const key = cell(p[0], p[1]);
      if (!hash.has(key)) hash.set(key, []);
      hash.get(key).push(site);
    }
  }
  let stray = 0, wrong = 0;
  const residuals = [];
  // The drawn size and paint of a stroke: a part put where another belongs differs.
  const look = (st) => {
    const xs = st.points.map((q) => q[0]), ys = st.points.map((q) => q[1]);
    return [Math.max(...xs) - Math.min(...xs), Math.max(...ys) - Math.min(...ys), st.stroke ?? '', st.fill ?? ''];
  };
  const looks = strokes.map(look);
  out.strokes.forEach((s, idx) => {
    const [x, y] = centre(s);
    let best = null, bd = Infinity;
    near(x, y, out.classes[idx], (site) => {
      const d = Math.hypot(site.p[0] - x, site.p[1] - y);
      if (d < bd) { bd = d; best = site; }
    });
    if (best && bd < tol) {
      best.hits++;
      residuals.push(bd / period);
      const [a, b] = [look(s), looks[best.k]];
      if (Math.abs(a[0] - b[0]) > 0.5 || Math.abs(a[1] - b[1]) > 0.5 || a[2] !== b[2] || a[3] !== b[3]) wrong++;
    } else stray++;
  });
  residuals.sort((p, q) => p - q);
  // Every site whose drawing is in the area (clearly: by more than the tolerance).
  const inner = sites.filter((s) => s.inside);
  const covered = inner.filter((s) => s.hits > 0).length;
  const stacked = sites.reduce((n, s) => n + Math.max(0, s.hits - 1), 0);
  return {
    corpus: c.corpus, name: c.name, example: strokes.length, out: out.strokes.length, sites: inner.length,
    recall: covered / inner.length, stray, stacked, wrong, drift: residuals[Math.floor(0.95 * (residuals.length - 1))] ?? 0, ms,
  };
}
