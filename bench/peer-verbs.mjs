// Issue 30's verbs against their equivalents in Embark's texture-synthesis 0.8.3 CLI
// (`cargo install --locked texture-synthesis-cli --version 0.8.3`), on photographs and
// hole masks from a data folder, seeds 1-3, through the built package in Node.
//
//   node bench/peer-verbs.mjs [data dir] [--seeds N] [--only a,b] [--verbs v1,v2] [--workers N] [--no-default-threads] [--time-only]
//
// The data folder (default /tmp/peer30/data) holds NAME.png (a photograph, about 192-256
// px a side) and NAME.hole.png (opaque white where the hole is), and optionally
// target.style.png (the target of style transfer; a disc is used otherwise). Outputs go
// to /tmp/peer30/out/<verb>/, contact sheets to /tmp/peer30/out/sheet-<verb>.png, and
// markdown tables to stdout. Without `texture-synthesis` on PATH only ours runs.
//
// Measures (the same code for both synthesizers; computed afterwards in worker threads,
// `--workers N`, default one per core, so they never overlap the timed runs):
// - patch energy: for 7x7 windows of the output (centred on hole / band pixels, every
//   3rd in raster order; for whole outputs on every 3rd row and column), the RMS RGB
//   distance (0-255) to the best-matching 7x7 window of the source (exact nearest
//   neighbour), averaged. Lower = output windows are closer to windows of the source.
// - edge ratio: mean RGB step (Euclidean) across the hole's boundary (a hole pixel and its
//   4-neighbour outside) over the mean step of 4-neighbour pairs both outside and within
//   8 px of the hole. About 1 = no visible edge.
// - seam score: mean step across the wrap of the tile repeated 2x2 over the mean step
//   between neighbouring pixels elsewhere.
// Times: ours is the call alone (wasm, one thread); the peer's is the whole process
// (PNG decoding and encoding included), `--threads 1`, and with its default threads.
import { readFileSync, writeFileSync, mkdirSync, readdirSync, existsSync } from 'node:fs';
import { spawnSync } from 'node:child_process';
import { join } from 'node:path';
import { Worker, isMainThread, parentPort } from 'node:worker_threads';
import { availableParallelism } from 'node:os';
import * as ps from '../pkg/node/index.js';

// ---------------------------------------------------------------- arguments
const argv = process.argv.slice(2);
const flag = (name) => { const i = argv.indexOf(name); if (i < 0) return null; const v = argv[i + 1]; argv.splice(i, 2); return v; };
const seedsN = Number(flag('--seeds') ?? 3);
const only = flag('--only')?.split(',') ?? null;
const verbsOnly = flag('--verbs')?.split(',') ?? null;
const noDefaultThreads = argv.includes('--no-default-threads');
const timeOnly = argv.includes('--time-only'); // skip the measures, sheets and quality tables
const dataDir = argv.find((a) => !a.startsWith('--')) ?? '/tmp/peer30/data';
const outDir = '/tmp/peer30/out';
const seeds = Array.from({ length: seedsN }, (_, i) => i + 1);
const SIDE = 256; // output side of the synthesis verbs
const PEER = 'texture-synthesis';
const workersN = Number(flag('--workers') ?? availableParallelism());

// ---------------------------------------------------------------- images
const load = (p) => ps.decodeImage(readFileSync(p));
const save = (p, img) => writeFileSync(p, ps.encodePng(img));
const make = (w, h, f) => {
  const data = new Uint8ClampedArray(w * h * 4);
  for (let y = 0; y < h; y++) for (let x = 0; x < w; x++) data.set(f(x, y), 4 * (y * w + x));
  return { width: w, height: h, data };
};
const px = (img, x, y) => { const i = 4 * (y * img.width + x); return [img.data[i], img.data[i + 1], img.data[i + 2], 255]; };
const crop = (img, x0, y0, w, h) => make(w, h, (x, y) => px(img, x0 + x, y0 + y));
const maskOf = (img) => { // opaque white (alpha and luminance at least half) = true
  const m = new Uint8Array(img.width * img.height);
  for (let i = 0; i < m.length; i++) {
    const d = img.data; const l = 0.299 * d[4 * i] + 0.587 * d[4 * i + 1] + 0.114 * d[4 * i + 2];
    m[i] = d[4 * i + 3] >= 128 && l >= 128 ? 1 : 0;
  }
  return m;
};
const maskImage = (w, h, m, invert = false) => make(w, h, (x, y) => { const v = (m[y * w + x] ? 255 : 0) ^ (invert ? 255 : 0); return [v, v, v, 255]; });
const grey = (w, h, v) => make(w, h, (x, y) => { const g = Math.round(Math.max(0, Math.min(255, v[y * w + x]))); return [g, g, g, 255]; });
const lum = (img) => { const n = img.width * img.height, l = new Float64Array(n); for (let i = 0; i < n; i++) l[i] = 0.299 * img.data[4 * i] + 0.587 * img.data[4 * i + 1] + 0.114 * img.data[4 * i + 2]; return l; };
const blur = (v, w, h, sigma = 4) => {
  const r = Math.ceil(3 * sigma), k = []; let s = 0;
  for (let i = -r; i <= r; i++) { k.push(Math.exp(-(i * i) / (2 * sigma * sigma))); s += k[k.length - 1]; }
  const kk = k.map((a) => a / s), t = new Float64Array(w * h), o = new Float64Array(w * h);
  const cl = (a, n) => (a < 0 ? 0 : a >= n ? n - 1 : a);
  for (let y = 0; y < h; y++) for (let x = 0; x < w; x++) { let a = 0; for (let i = -r; i <= r; i++) a += kk[i + r] * v[y * w + cl(x + i, w)]; t[y * w + x] = a; }
  for (let y = 0; y < h; y++) for (let x = 0; x < w; x++) { let a = 0; for (let i = -r; i <= r; i++) a += kk[i + r] * t[cl(y + i, h) * w + x]; o[y * w + x] = a; }
  return o;
};
const corr = (a, b) => {
  const n = a.length; let ma = 0, mb = 0; for (let i = 0; i < n; i++) { ma += a[i]; mb += b[i]; } ma /= n; mb /= n;
  let sab = 0, saa = 0, sbb = 0; for (let i = 0; i < n; i++) { const da = a[i] - ma, db = b[i] - mb; sab += da * db; saa += da * da; sbb += db * db; }
  return sab / Math.sqrt(saa * sbb || 1);
};
const resize = (img, w, h) => make(w, h, (x, y) => px(img, Math.min(img.width - 1, Math.floor(((x + 0.5) * img.width) / w)), Math.min(img.height - 1, Math.floor(((y + 0.5) * img.height) / h))));
const tile2 = (img) => make(2 * img.width, 2 * img.height, (x, y) => px(img, x % img.width, y % img.height));
const step = (a, i, j) => { const d = a.data; const r = d[4 * i] - d[4 * j], g = d[4 * i + 1] - d[4 * j + 1], b = d[4 * i + 2] - d[4 * j + 2]; return Math.sqrt(r * r + g * g + b * b); };
const percentile = (v, p) => { const s = Float64Array.from(v).sort(); return s[Math.min(s.length - 1, Math.floor(p * s.length))]; };

// ---------------------------------------------------------------- patch energy (exact NN)
const R = 3, D = 3 * (2 * R + 1) ** 2, K = 12; // 7x7 RGB windows, 12 PCA dimensions for pruning
function windowAt(img, cx, cy, wrap, out) {
  const { width: w, height: h, data } = img; let k = 0;
  for (let dy = -R; dy <= R; dy++) for (let dx = -R; dx <= R; dx++) {
    let x = cx + dx, y = cy + dy;
    if (wrap) { x = (x + w) % w; y = (y + h) % h; }
    const i = 4 * (y * w + x); out[k++] = data[i]; out[k++] = data[i + 1]; out[k++] = data[i + 2];
  }
  return out;
}
// A searchable set of source windows: from several images, each window wholly inside
// its image and (with `exclude`) touching no excluded pixel; `label` = image index.
function windowSet(images, excludes = []) {
  const rows = [], labels = [], pos = [], lookup = images.map((img) => new Int32Array(img.width * img.height).fill(-1));
  images.forEach((img, li) => {
    const ex = excludes[li];
    for (let y = R; y < img.height - R; y++) for (let x = R; x < img.width - R; x++) {
      if (ex) { let bad = false; for (let dy = -R; dy <= R && !bad; dy++) for (let dx = -R; dx <= R; dx++) if (ex[(y + dy) * img.width + x + dx]) { bad = true; break; } if (bad) continue; }
      lookup[li][y * img.width + x] = rows.length; pos.push(x, y); rows.push(windowAt(img, x, y, false, new Float32Array(D))); labels.push(li);
    }
  });
  const n = rows.length, V = new Float32Array(n * D);
  rows.forEach((r, i) => V.set(r, i * D));
  // PCA basis by subspace iteration on the covariance of a subsample.
  const mean = new Float64Array(D); for (let i = 0; i < n; i++) for (let d = 0; d < D; d++) mean[d] += V[i * D + d] / n;
  const C = new Float64Array(D * D), stepS = Math.max(1, Math.floor(n / 4000)), c = new Float64Array(D); let m = 0;
  for (let i = 0; i < n; i += stepS) { for (let d = 0; d < D; d++) c[d] = V[i * D + d] - mean[d]; for (let a = 0; a < D; a++) for (let b = a; b < D; b++) C[a * D + b] += c[a] * c[b]; m++; }
  for (let a = 0; a < D; a++) for (let b = a; b < D; b++) C[b * D + a] = C[a * D + b] /= m;
  let Q = Array.from({ length: K }, (_, k) => Float64Array.from({ length: D }, (_, d) => Math.sin(1 + d * (k + 1) * 0.7) + (d === k ? 1 : 0)));
  for (let it = 0; it < 40; it++) {
    Q = Q.map((q) => { const o = new Float64Array(D); for (let a = 0; a < D; a++) { let s = 0; for (let b = 0; b < D; b++) s += C[a * D + b] * q[b]; o[a] = s; } return o; });
    for (let k = 0; k < K; k++) { for (let j = 0; j < k; j++) { let dot = 0; for (let d = 0; d < D; d++) dot += Q[k][d] * Q[j][d]; for (let d = 0; d < D; d++) Q[k][d] -= dot * Q[j][d]; } let nn = 0; for (let d = 0; d < D; d++) nn += Q[k][d] ** 2; nn = Math.sqrt(nn) || 1; for (let d = 0; d < D; d++) Q[k][d] /= nn; }
  }
  const P = new Float32Array(n * K);
  for (let i = 0; i < n; i++) for (let k = 0; k < K; k++) { let s = 0; for (let d = 0; d < D; d++) s += (V[i * D + d] - mean[d]) * Q[k][d]; P[i * K + k] = s; }
  // Clusters in the projected space (k-means fitted on a subsample), each with its
  // radius, for pruning.
  const NC = Math.max(1, Math.round(Math.sqrt(n))), cent = new Float64Array(NC * K), assign = new Int32Array(n);
  for (let c = 0; c < NC; c++) { const i = Math.floor(((c + 0.5) * n) / NC); for (let k = 0; k < K; k++) cent[c * K + k] = P[i * K + k]; }
  const closest = (i) => { let bc = 0, bd = Infinity; for (let c = 0; c < NC; c++) { let s = 0; for (let k = 0; k < K; k++) { const t = P[i * K + k] - cent[c * K + k]; s += t * t; if (s >= bd) break; } if (s < bd) { bd = s; bc = c; } } return bc; };
  const sstep = Math.max(1, Math.floor(n / 12000));
  for (let it = 0; it < 6; it++) {
    const sum = new Float64Array(NC * K), cnt = new Int32Array(NC);
    for (let i = 0; i < n; i += sstep) { const c = closest(i); cnt[c]++; for (let k = 0; k < K; k++) sum[c * K + k] += P[i * K + k]; }
    for (let c = 0; c < NC; c++) if (cnt[c]) for (let k = 0; k < K; k++) cent[c * K + k] = sum[c * K + k] / cnt[c];
  }
  for (let i = 0; i < n; i++) assign[i] = closest(i);
  const members = Array.from({ length: NC }, () => []), radius = new Float64Array(NC);
  for (let i = 0; i < n; i++) { const c = assign[i]; members[c].push(i); let s = 0; for (let k = 0; k < K; k++) s += (P[i * K + k] - cent[c * K + k]) ** 2; radius[c] = Math.max(radius[c], Math.sqrt(s)); }
  return { n, V, P, Q, mean, labels: Uint8Array.from(labels), pos: Int32Array.from(pos), lookup, dims: images.map((i) => [i.width, i.height]), NC, cent, radius, members: members.map((m) => Int32Array.from(m)) };
}
// Exact nearest window: distances in the orthonormal projected space are lower bounds of
// true ones, and a cluster's members are at least (distance to its centre - its radius) away.
function nearest(set, q, hints = []) {
  const { V, P, Q, mean, NC, cent, radius, members } = set, pq = new Float64Array(K);
  for (let k = 0; k < K; k++) { let s = 0; for (let d = 0; d < D; d++) s += (q[d] - mean[d]) * Q[k][d]; pq[k] = s; }
  const clb = new Float64Array(NC);
  for (let c = 0; c < NC; c++) { let s = 0; for (let k = 0; k < K; k++) { const t = pq[k] - cent[c * K + k]; s += t * t; } const g = Math.max(0, Math.sqrt(s) - radius[c]); clb[c] = g * g; }
  let best = Infinity, bi = 0;
  for (const i of hints) { // candidates from neighbouring queries (coherence): a tight bound early
    let s = 0; const od = i * D; let d = 0;
    for (; d < D; d++) { const t = V[od + d] - q[d]; s += t * t; if (s >= best) break; }
    if (d === D) { best = s; bi = i; }
  }
  const visit = (c) => {
    for (const i of members[c]) {
      let s = 0; const o = i * K; for (let k = 0; k < K; k++) { const t = P[o + k] - pq[k]; s += t * t; }
      if (s >= best) continue;
      s = 0; const od = i * D; let d = 0;
      for (; d < D; d++) { const t = V[od + d] - q[d]; s += t * t; if (s >= best) break; }
      if (d === D) { best = s; bi = i; }
    }
  };
  const order = Array.from({ length: NC }, (_, c) => c).sort((a, b) => clb[a] - clb[b]);
  for (const c of order) { if (clb[c] >= best) break; visit(c); }
  return { d2: best, index: bi, label: set.labels[bi] };
}
// Mean RMS distance of output windows at `centres` to their nearest source window.
function patchEnergy(img, centres, set, wrap = false) {
  const q = new Float32Array(D); let sum = 0; const counts = new Map(), done = [];
  for (const [x, y] of centres) {
    const hints = [];
    for (let k = done.length - 1, seen = 0; k >= 0 && seen < 4; k--) { // the last few queries' matches, shifted
      const [px, py, i] = done[k]; if (Math.abs(px - x) > 9 || Math.abs(py - y) > 9) continue; seen++;
      const l = set.labels[i], [w, h] = set.dims[l], sx = set.pos[2 * i] + x - px, sy = set.pos[2 * i + 1] + y - py;
      if (sx >= 0 && sy >= 0 && sx < w && sy < h && set.lookup[l][sy * w + sx] >= 0) hints.push(set.lookup[l][sy * w + sx]);
    }
    const r = nearest(set, windowAt(img, x, y, wrap, q), hints);
    done.push([x, y, r.index]); if (done.length > 200) done.splice(0, 100);
    sum += Math.sqrt(r.d2 / D); counts.set(r.label, (counts.get(r.label) ?? 0) + 1);
  }
  return { energy: sum / centres.length, counts, n: centres.length };
}
const gridCentres = (w, h, s = 3) => { const c = []; for (let y = R; y < h - R; y += s) for (let x = R; x < w - R; x += s) c.push([x, y]); return c; };
const maskCentres = (w, h, m, wrap, s = 3) => { const c = []; let k = 0; for (let y = 0; y < h; y++) for (let x = 0; x < w; x++) { if (!m[y * w + x]) continue; if (!wrap && (x < R || y < R || x >= w - R || y >= h - R)) continue; if (k++ % s === 0) c.push([x, y]); } return c; };

// ---------------------------------------------------------------- other measures
function edgeRatio(img, m) {
  const { width: w, height: h } = img, dist = new Int32Array(w * h).fill(1e9), queue = [];
  for (let i = 0; i < w * h; i++) if (m[i]) { dist[i] = 0; queue.push(i); }
  for (let qi = 0; qi < queue.length; qi++) { // Chebyshev distance to the hole
    const i = queue[qi], x = i % w, y = (i / w) | 0;
    for (let dy = -1; dy <= 1; dy++) for (let dx = -1; dx <= 1; dx++) { const X = x + dx, Y = y + dy; if (X < 0 || Y < 0 || X >= w || Y >= h) continue; const j = Y * w + X; if (dist[j] > dist[i] + 1) { dist[j] = dist[i] + 1; queue.push(j); } }
  }
  let across = 0, na = 0, near = 0, nn = 0;
  for (let y = 0; y < h; y++) for (let x = 0; x < w; x++) for (const [X, Y] of [[x + 1, y], [x, y + 1]]) {
    if (X >= w || Y >= h) continue; const i = y * w + x, j = Y * w + X;
    if (m[i] !== m[j]) { across += step(img, i, j); na++; } else if (!m[i] && dist[i] <= 8 && dist[j] <= 8) { near += step(img, i, j); nn++; }
  }
  return across / na / (near / nn);
}
function seamScore(tile) {
  const t = tile2(tile), { width: W, height: H } = t, w = tile.width, h = tile.height; let a = 0, na = 0, e = 0, ne = 0;
  for (let y = 0; y < H; y++) for (let x = 0; x < W; x++) {
    if (x + 1 < W) { const s = step(t, y * W + x, y * W + x + 1); if ((x + 1) % w === 0) { a += s; na++; } else { e += s; ne++; } }
    if (y + 1 < H) { const s = step(t, y * W + x, (y + 1) * W + x); if ((y + 1) % h === 0) { a += s; na++; } else { e += s; ne++; } }
  }
  return a / na / (e / ne);
}
const changed = (a, b, m, want) => { let c = 0; for (let i = 0; i < m.length; i++) if (!!m[i] === want) for (let k = 0; k < 3; k++) if (a.data[4 * i + k] !== b.data[4 * i + k]) { c++; break; } return c; };
const LOGO = [230, 0, 200]; // magenta, painted as the region to keep out
const logoLike = (img) => { let c = 0; for (let i = 0; i < img.width * img.height; i++) { const d = img.data; if (Math.hypot(d[4 * i] - LOGO[0], d[4 * i + 1] - LOGO[1], d[4 * i + 2] - LOGO[2]) < 60) c++; } return c; };

// ---------------------------------------------------------------- measuring (in worker threads)
// One job: a verb on one photograph, every output (ours and the peer's, all seeds).
function measure({ v, ctx, imgs }) {
  const { photo, W, H, hole, band, logoPhoto, logoM, parts, discV, styleTarget } = ctx;
  const photoSet = () => windowSet([photo]);
  let out = [], ref = {};
  if (v === 'inpaint') {
    const set = windowSet([photo], [hole]), cs = maskCentres(W, H, hole, false);
    out = imgs.map((img) => ({ kept: changed(img, photo, hole, false), pe: patchEnergy(img, cs, set).energy, edge: edgeRatio(img, hole) }));
    ref = { pe: patchEnergy(photo, cs, set).energy, edge: edgeRatio(photo, hole) };
  } else if (v === 'mend') {
    const set = photoSet(), cs = maskCentres(W, H, band, true);
    out = imgs.map((img) => ({ seam: seamScore(img), kept: 1 - changed(img, photo, new Uint8Array(W * H), false) / (W * H), inner: changed(img, photo, band, false), pe: patchEnergy(img, cs, set, true).energy }));
    ref = { seam: seamScore(photo), pe: patchEnergy(photo, cs, set, true).energy };
  } else if (v === 'samplemask') {
    const set = windowSet([logoPhoto], [logoM]), cs = gridCentres(SIDE, SIDE);
    out = imgs.map((img) => ({ logo: logoLike(img), pe: patchEnergy(img, cs, set).energy }));
    ref = { logo: logoLike(logoPhoto) };
  } else if (v === 'guided') {
    const set = photoSet(), cs = gridCentres(SIDE, SIDE);
    out = imgs.map((img) => ({ corr: corr(blur(lum(img), SIDE, SIDE, 4), discV), pe: patchEnergy(img, cs, set).energy }));
  } else if (v === 'multi') {
    const set = windowSet(parts), cs = gridCentres(SIDE, SIDE);
    out = imgs.map((img) => { const p = patchEnergy(img, cs, set); return { pe: p.energy, share: [0, 1, 2].map((k) => (p.counts.get(k) ?? 0) / p.n) }; });
  } else if (v === 'style') {
    const set = photoSet(), t = blur(lum(styleTarget), SIDE, SIDE, 4), cs = gridCentres(SIDE, SIDE);
    out = imgs.map((img) => ({ corr: corr(blur(lum(img), SIDE, SIDE, 4), t), pe: patchEnergy(img, cs, set).energy }));
  } else if (v === 'plain') {
    const set = photoSet(), cs = gridCentres(SIDE, SIDE);
    out = imgs.map((img) => ({ pe: patchEnergy(img, cs, set).energy }));
  }
  return { out, ref };
}
if (!isMainThread) parentPort.on('message', (job) => parentPort.postMessage(measure(job)));

// ---------------------------------------------------------------- running
const median = (v) => { const s = [...v].filter((x) => x !== undefined && !Number.isNaN(x)).sort((a, b) => a - b); return s.length ? (s.length % 2 ? s[s.length >> 1] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2) : NaN; };
const timeIt = (f) => { const t = performance.now(); const r = f(); return { r, ms: performance.now() - t }; };
function peer(args, out, threads = 1) {
  const full = ['--no-progress', '-o', out, ...(threads ? ['--threads', String(threads)] : []), ...args];
  const t = performance.now(); const p = spawnSync(PEER, full, { encoding: 'utf8' }); const ms = performance.now() - t;
  if (p.status !== 0) throw new Error(`${PEER} ${full.join(' ')}: ${p.stderr}`);
  return { ms, img: threads ? load(out) : null };
}

if (isMainThread) await main();
async function main() {
const hasPeer = spawnSync(PEER, ['--version']).status === 0;
mkdirSync(outDir, { recursive: true });
const names = readdirSync(dataDir).filter((f) => /^[^.]+\.png$/.test(f)).map((f) => f.slice(0, -4)).filter((n) => !only || only.includes(n)).sort();
const styleTarget = existsSync(join(dataDir, 'target.style.png')) ? resize(load(join(dataDir, 'target.style.png')), SIDE, SIDE) : grey(SIDE, SIDE, Float64Array.from({ length: SIDE * SIDE }, (_, i) => (Math.hypot((i % SIDE) - SIDE / 2, ((i / SIDE) | 0) - SIDE / 2) < SIDE / 3 ? 220 : 30)));
const VERBS = ['inpaint', 'mend', 'samplemask', 'guided', 'multi', 'style', 'plain'].filter((v) => !verbsOnly || verbsOnly.includes(v));
for (const v of VERBS) mkdirSync(join(outDir, v), { recursive: true });
const inDir = join(outDir, 'in'); mkdirSync(inDir, { recursive: true });
const res = {}; // res[verb][name] = { ours: [{...}], peer: [...], ref: {...}, peerDefaultMs: [] }
const sheets = Object.fromEntries(VERBS.map((v) => [v, []]));
const measureJobs = []; // [verb, name, ctx, entries]
ps.synthesizeTexture(make(64, 64, (x, y) => [x * 4, y * 4, (x * y) & 255, 255]), { width: 64, height: 64 }); // warm-up

for (const name of names) {
  const photo = load(join(dataDir, `${name}.png`)), W = photo.width, H = photo.height;
  const holeImg = join(dataDir, `${name}.hole.png`); const hole = maskOf(load(holeImg));
  const photoPath = join(inDir, `${name}.png`); save(photoPath, photo);
  const put = (v, who, seed, img) => save(join(outDir, v, `${name}.${who}.s${seed}.png`), img);
  const rec = (v) => (res[v] ??= {})[name] ??= { ours: [], peer: [], ref: {}, peerDefaultMs: [] };
  const S = `${W}x${H}`;

  // Inputs each verb needs.
  const hint = { peerHole: join(inDir, `${name}.hole.peer.png`) }; save(hint.peerHole, maskImage(W, H, hole, true));
  const bandPx = Math.round(0.125 * W), bandPy = Math.round(0.125 * H);
  const band = Uint8Array.from({ length: W * H }, (_, i) => { const x = i % W, y = (i / W) | 0; return x < bandPx || x >= W - bandPx || y < bandPy || y >= H - bandPy ? 1 : 0; });
  hint.peerBand = join(inDir, `${name}.band.peer.png`); save(hint.peerBand, maskImage(W, H, band, true));
  const L0 = Math.round(W * 0.07), L1 = L0 + Math.round(W * 0.25); // the painted logo square
  const logoM = Uint8Array.from({ length: W * H }, (_, i) => { const x = i % W, y = (i / W) | 0; return x >= L0 && x < L1 && y >= L0 && y < L1 ? 1 : 0; });
  const logoPhoto = make(W, H, (x, y) => (logoM[y * W + x] ? [...LOGO, 255] : px(photo, x, y)));
  hint.logoPhoto = join(inDir, `${name}.logo.png`); save(hint.logoPhoto, logoPhoto);
  hint.peerLogoMask = join(inDir, `${name}.logo.peer.png`); save(hint.peerLogoMask, maskImage(W, H, logoM, true));
  const exGuideV = blur(lum(photo), W, H, 4), exGuide = grey(W, H, exGuideV);
  const lo = percentile(exGuideV, 0.1), hi = percentile(exGuideV, 0.9);
  const discV = blur(Float64Array.from({ length: SIDE * SIDE }, (_, i) => (Math.hypot((i % SIDE) - SIDE / 2, ((i / SIDE) | 0) - SIDE / 2) < SIDE * 0.3 ? hi : lo)), SIDE, SIDE, 2);
  const disc = grey(SIDE, SIDE, discV);
  hint.exGuide = join(inDir, `${name}.exguide.png`); save(hint.exGuide, exGuide);
  hint.disc = join(inDir, `${name}.disc.png`); save(hint.disc, disc);
  const hw = W >> 1, hh = H >> 1;
  const parts = [crop(photo, 0, 0, hw, hh), crop(photo, hw, 0, hw, hh), crop(photo, hw >> 1, hh, hw, hh)];
  hint.parts = parts.map((p, i) => { const f = join(inDir, `${name}.part${i}.png`); save(f, p); return f; });
  hint.style = join(inDir, 'target.style.png'); save(hint.style, styleTarget);

  const jobs = {
    inpaint: {
      ours: (seed) => ps.inpaintTexture(photo, maskImage(W, H, hole), { seed }),
      peer: ['--inpaint', hint.peerHole, '--out-size', S, 'generate', photoPath],
    },
    mend: {
      ours: (seed) => ps.seamlessTile(photo, { method: 'mend', seed }).image,
      ours25: (seed) => ps.seamlessTile(photo, { method: 'mend', band: 0.25, seed }).image,
      peer: ['--tiling', '--inpaint', hint.peerBand, '--out-size', S, 'generate', photoPath],
    },
    samplemask: {
      ours: (seed) => ps.synthesizeTexture(logoPhoto, { width: SIDE, height: SIDE, seed, sampleMask: maskImage(W, H, logoM) }),
      peer: ['--sample-masks', hint.peerLogoMask, '--out-size', String(SIDE), 'generate', hint.logoPhoto],
    },
    guided: {
      ours: (seed) => ps.synthesizeTexture(photo, { width: SIDE, height: SIDE, seed, guides: { exemplar: exGuide, target: disc } }),
      peer: ['--out-size', String(SIDE), 'generate', '--guides', hint.exGuide, '--target-guide', hint.disc, '--', photoPath],
    },
    multi: {
      ours: (seed) => ps.synthesizeTexture(parts, { width: SIDE, height: SIDE, seed }),
      peer: ['--out-size', String(SIDE), 'generate', ...hint.parts],
    },
    style: {
      ours: (seed) => ps.transferStyle(photo, styleTarget, { seed }),
      peer: ['--out-size', String(SIDE), 'transfer-style', '--style', photoPath, '--guide', hint.style],
    },
    plain: {
      ours: (seed) => ps.synthesizeTexture(photo, { width: SIDE, height: SIDE, seed }),
      peer: ['--out-size', String(SIDE), 'generate', photoPath],
    },
  };

  for (const v of VERBS) {
    const r = rec(v), job = jobs[v];
    for (const seed of seeds) { // interleaved: ours, then the peer, same input and seed
      const o = timeIt(() => job.ours(seed)); put(v, 'ours', seed, o.r); r.ours.push({ seed, ms: o.ms, img: o.r });
      if (job.ours25) { const o2 = timeIt(() => job.ours25(seed)); put(v, 'ours25', seed, o2.r); (r.ours25 ??= []).push({ seed, ms: o2.ms, img: o2.r }); }
      if (hasPeer) { const out = join(outDir, v, `${name}.peer.s${seed}.png`); const p = peer(['--seed', String(seed), ...job.peer], out); r.peer.push({ seed, ms: p.ms, img: p.img }); }
    }
    if (hasPeer && !noDefaultThreads) for (const seed of seeds) r.peerDefaultMs.push(peer(['--seed', String(seed), ...job.peer], join(outDir, v, `${name}.peer-mt.s${seed}.png`), 0).ms);
    process.stderr.write(`${name} ${v}: ours ${median(r.ours.map((x) => x.ms)).toFixed(0)} ms${hasPeer ? `, peer ${median(r.peer.map((x) => x.ms)).toFixed(0)} ms` : ''}\n`);
  }

  // ---- what to measure later, and the contact sheets' rows
  const ctx = { photo, W, H, hole, band, logoPhoto, logoM, parts, discV, styleTarget };
  for (const v of VERBS) {
    const r = res[v][name]; measureJobs.push([v, name, ctx, [...r.ours, ...(r.ours25 ?? []), ...r.peer]]);
    const o = r.ours[0].img, pe = r.peer[0]?.img;
    sheets[v].push({
      inpaint: () => [make(W, H, (x, y) => (hole[y * W + x] ? [255, 0, 255, 255] : px(photo, x, y))), o, pe],
      mend: () => [tile2(photo), tile2(o), pe && tile2(pe)],
      samplemask: () => [logoPhoto, o, pe],
      guided: () => [photo, exGuide, disc, o, pe],
      multi: () => [make(W, H, (x, y) => { const k = y < hh ? (x < hw ? 0 : 1) : 2; const p = parts[k], X = k === 2 ? x - (hw >> 1) : x % hw, Y = y % hh; return X >= 0 && X < hw ? px(p, X, Y) : [40, 40, 40, 255]; }), o, pe],
      style: () => [photo, styleTarget, o, pe],
      plain: () => [photo, o, pe],
    }[v]());
  }
}

// ---------------------------------------------------------------- measures, in parallel
if (!timeOnly) {
  const queue = [...measureJobs]; let done = 0;
  const run = (w) => new Promise((resolve) => {
    const next = () => {
      const job = queue.shift(); if (!job) { w.terminate(); resolve(); return; }
      const [v, name, ctx, entries] = job;
      w.once('message', ({ out, ref }) => {
        entries.forEach((e, i) => { Object.assign(e, out[i]); delete e.img; });
        res[v][name].ref = ref; process.stderr.write(`measured ${name} ${v} (${++done}/${measureJobs.length})\n`); next();
      });
      w.postMessage({ v, ctx, imgs: entries.map((e) => e.img) });
    };
    next();
  });
  await Promise.all(Array.from({ length: Math.max(1, Math.min(workersN, queue.length)) }, () => run(new Worker(new URL(import.meta.url)))));
}

// ---------------------------------------------------------------- contact sheets
// (In pages of at most 4096 pixels high, the largest PNG the package encodes:
// sheet-<verb>.png, then sheet-<verb>-2.png and on.)
if (!timeOnly) for (const v of VERBS) {
  const all = sheets[v]; if (!all.length) continue;
  const gap = 6, colW = [], height = (r) => Math.max(...r.filter(Boolean).map((i) => i.height));
  for (const r of all) r.forEach((img, c) => { colW[c] = Math.max(colW[c] ?? 0, img?.width ?? 0); });
  const pages = [[]]; let used = gap;
  for (const r of all) {
    if (pages.at(-1).length && used + height(r) + gap > 4096) { pages.push([]); used = gap; }
    pages.at(-1).push(r); used += height(r) + gap;
  }
  pages.forEach((rows, p) => {
    const rowH = rows.map(height);
    const Wt = colW.reduce((a, b) => a + b + gap, gap), Ht = rowH.reduce((a, b) => a + b + gap, gap);
    const sheet = make(Wt, Ht, () => [128, 128, 128, 255]);
    let y0 = gap;
    rows.forEach((r, ri) => {
      let x0 = gap;
      r.forEach((img, c) => { if (img) for (let y = 0; y < img.height; y++) for (let x = 0; x < img.width; x++) sheet.data.set(px(img, x, y), 4 * ((y0 + y) * Wt + x0 + x)); x0 += colW[c] + gap; });
      y0 += rowH[ri] + gap;
    });
    save(join(outDir, `sheet-${v}${p ? `-${p + 1}` : ''}.png`), sheet);
  });
}

// ---------------------------------------------------------------- tables
const f2 = (x) => (x === undefined || Number.isNaN(x) ? '–' : x.toFixed(2));
const f1 = (x) => (x === undefined || Number.isNaN(x) ? '–' : x.toFixed(1));
const f0 = (x) => (x === undefined || Number.isNaN(x) ? '–' : x.toFixed(0));
const pct = (x) => (x === undefined || Number.isNaN(x) ? '–' : `${(100 * x).toFixed(1)}%`);
const med = (arr, k) => median((arr ?? []).map((e) => e[k]));
const table = (title, head, rowsOf) => {
  if (!res[title.key] || timeOnly) return;
  console.log(`\n### ${title.text}\n\n| photo | ${head.join(' | ')} |\n|---|${head.map(() => '---:').join('|')}|`);
  for (const name of names) if (res[title.key][name]) console.log(`| ${name} | ${rowsOf(res[title.key][name]).join(' | ')} |`);
  const colsAll = names.filter((n) => res[title.key][n]).map((n) => rowsOf(res[title.key][n]).map((v) => (/^-?[\d.]+%?$/.test(v) ? Number.parseFloat(v) : NaN)));
  const cells = names.filter((n) => res[title.key][n]).map((n) => rowsOf(res[title.key][n]));
  console.log(`| **median** | ${head.map((_, c) => { const m = median(colsAll.map((r) => r[c])); return Number.isNaN(m) ? '' : cells.some((r) => String(r[c]).endsWith('%')) ? `${m.toFixed(1)}%` : m.toFixed(2); }).join(' | ')} |`);
};
console.log(`Medians over seeds ${seeds.join(', ')}; patch energy = mean RMS (0-255) of 7x7 windows to the nearest source window. Peer: texture-synthesis 0.8.3 ${hasPeer ? '' : '(not on PATH: skipped)'}`);
table({ key: 'inpaint', text: 'Inpainting (hole pixels re-made; kept = unmasked pixels that differ)' },
  ['kept≠ ours', 'kept≠ peer', 'PE ours', 'PE peer', 'PE photo', 'edge ours', 'edge peer', 'edge photo'],
  (r) => [f0(med(r.ours, 'kept')), f0(med(r.peer, 'kept')), f1(med(r.ours, 'pe')), f1(med(r.peer, 'pe')), f1(r.ref.pe), f2(med(r.ours, 'edge')), f2(med(r.peer, 'edge')), f2(r.ref.edge)]);
table({ key: 'mend', text: 'Mend into a tile (band 0.25: outer 12.5% of each side re-made)' },
  ['seam ours', 'seam ours b.25', 'seam peer', 'seam photo', 'kept ours', 'kept peer', 'inner≠ ours', 'inner≠ peer', 'PE band ours', 'PE band peer', 'PE band photo'],
  (r) => [f2(med(r.ours, 'seam')), f2(med(r.ours25, 'seam')), f2(med(r.peer, 'seam')), f2(r.ref.seam), pct(med(r.ours, 'kept')), pct(med(r.peer, 'kept')), f0(med(r.ours, 'inner')), f0(med(r.peer, 'inner')), f1(med(r.ours, 'pe')), f1(med(r.peer, 'pe')), f1(r.ref.pe)]);
table({ key: 'samplemask', text: `Sample mask (magenta logo square kept out; logo-like = output pixels within 60 of its colour, of ${SIDE}²)` },
  ['logo-like ours', 'logo-like peer', 'in photo', 'PE ours', 'PE peer'],
  (r) => [f0(med(r.ours, 'logo')), f0(med(r.peer, 'logo')), f0(r.ref.logo), f1(med(r.ours, 'pe')), f1(med(r.peer, 'pe'))]);
table({ key: 'guided', text: 'Guided synthesis (exemplar guide: blurred luminance; target: a disc)' },
  ['corr ours', 'corr peer', 'PE ours', 'PE peer'],
  (r) => [f2(med(r.ours, 'corr')), f2(med(r.peer, 'corr')), f1(med(r.ours, 'pe')), f1(med(r.peer, 'pe'))]);
table({ key: 'multi', text: 'Three exemplars (quarter crops TL, TR, bottom middle); share = nearest window in each' },
  ['PE ours', 'PE peer', 'share ours', 'share peer'],
  (r) => [f1(med(r.ours, 'pe')), f1(med(r.peer, 'pe')), [0, 1, 2].map((k) => f2(median(r.ours.map((e) => e.share[k])))).join('/'), r.peer.length ? [0, 1, 2].map((k) => f2(median(r.peer.map((e) => e.share[k])))).join('/') : '–']);
table({ key: 'style', text: 'Style transfer (target: the style target image)' },
  ['corr ours', 'corr peer', 'PE ours', 'PE peer'],
  (r) => [f2(med(r.ours, 'corr')), f2(med(r.peer, 'corr')), f1(med(r.ours, 'pe')), f1(med(r.peer, 'pe'))]);
table({ key: 'plain', text: `Plain synthesis (${SIDE}²)` }, ['PE ours', 'PE peer'], (r) => [f1(med(r.ours, 'pe')), f1(med(r.peer, 'pe'))]);

console.log(`\n### Time (ms, median over photographs x seeds; ours: the call in wasm, one thread; peer: the whole process)\n\n| verb | ours | peer --threads 1 | peer default threads | peer t1 / ours |\n|---|---:|---:|---:|---:|`);
for (const v of VERBS) {
  const all = (k) => names.flatMap((n) => (res[v][n]?.[k] ?? []).map((e) => (typeof e === 'number' ? e : e.ms)));
  const o = median(all('ours')), p = median(all('peer')), pm = median(all('peerDefaultMs'));
  console.log(`| ${v}${v === 'mend' ? ` (band 0.25: ${f0(median(all('ours25')))})` : ''} | ${f0(o)} | ${f0(p)} | ${f0(pm)} | ${f2(p / o)} |`);
}
if (!timeOnly) console.log(`\nSheets: ${VERBS.map((v) => join(outDir, `sheet-${v}.png`)).join(', ')}`);
}
