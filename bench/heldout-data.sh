#!/usr/bin/env bash
# Held-out photographs for bench/peer-verbs.mjs (and tile tests), rebuilt the same way every run.
#
#   bash bench/heldout-data.sh
#
# 1. `apt-get download`s the Debian packages below that the apt sources here know (pinned to the
#    versions the set was picked from; the candidate version, with a warning, if that one is gone)
#    into /tmp/heldout/debs and extracts each with `dpkg-deb -x` into /tmp/heldout/pkgs/NAME.
#    Sweet Home 3D keeps its textures inside its jar; they are unpacked to /tmp/heldout/jar.
# 2. Takes the material photographs listed in PICKS (explicit paths, one word a name), crops the
#    central 85%, scales it (separable tent filter, antialiased when shrinking) so the longer side
#    is 224 px, and writes /tmp/peer30/data/NAME.png; the central square of the same crop scaled
#    to 128x128 goes to /tmp/peer25/data/NAME.png. The soft stochastic exemplars of SOFT
#    (clouds, mist, wisps, fire-smoke) get only that square, in /tmp/peer25/soft/NAME.png, and
#    the fresh ones of FRESH (helper-73's trial of issue 25) in /tmp/peer25/fresh/NAME.png.
# 3. Writes /tmp/peer30/data/NAME.hole.png, the same size: opaque white in the hole, opaque black
#    elsewhere. The hole is the union of 3-4 overlapping ellipses drawn from a PRNG seeded by the
#    name (FNV-1a -> mulberry32), scaled to cover 8.5-10.5% (checked: 8-11%) of the pixels and
#    moved, by whole pixels, to stay at least 12 px from the border.
#
# Image work uses the project's built package (pkg/node: decodeImage reads PNG and JPEG,
# encodePng writes), so the output does not depend on which of PIL / ImageMagick a machine has
# (neither is here: no PIL, and /usr/local/bin/convert is a stand-in, not ImageMagick).
# Needs: apt-get, dpkg-deb, node 20, the repository's pkg/node (build it first if missing), unzip or
# python3. Idempotent: what exists is reused; outputs are rewritten identically.
set -euo pipefail

ROOT=/tmp/heldout
DEBS=$ROOT/debs
PKGS=$ROOT/pkgs
JAR=$ROOT/jar
OUT30=/tmp/peer30/data
OUT25=/tmp/peer25/data
HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
PKG_NODE=$HERE/../pkg/node/index.js

# package=version the picks were made from (Debian bookworm). Only the first three are used by
# PICKS; the rest are fetched as the brief's pool to pick from later.
PACKAGES=(
  sweethome3d=7.0.2+dfsg-3
  extremetuxracer-data=0.8.2-1
  supertuxkart-data=1.4+dfsg-2
  trigger-rally-data=0.6.6.1-3
  colobot-common-textures=0.2.0-2
  gimp-data=2.10.34-1+deb12u10
  gimp-data-extras=1:2.0.2-1.1
)

SH3D=$JAR/com/eteks/sweethome3d/io/resources/textures
ETR=$PKGS/extremetuxracer-data/usr/share/games/etr/terrains
STK=$PKGS/supertuxkart-data/usr/share/games/supertuxkart/data/textures
# NAME  source file
PICKS=(
  "grass    $SH3D/grass.jpg"
  "gravel   $ETR/pebbles04.png"
  "stones   $ETR/pebbles01.png"
  "paving   $STK/Paving_stones_2.jpg"
  "brick    $STK/stk_generic_brickA.png"
  "roof     $STK/roof.png"
  "weave    $STK/stk_generic_wickerA.png"
  "bark     $STK/stktex_treeBark_a.png"
  "marble   $ETR/rock01.png"
  "sand     $ETR/sand01.png"
  "wood     $STK/stktex_generic_WoodG.png"
  "plaster  $SH3D/roughcast.jpg"
)

COLOBOT=$PKGS/colobot-common-textures/usr/share/games/colobot/textures
# Soft stochastic exemplars (issue 25's clouds and smoke; no smoke photograph was found in
# the packages: their smoke is sprites with alpha): only the 128x128 central square, to
# $OUT25S, for the tile and plain-synthesis measures.
OUT25S=/tmp/peer25/soft
SOFT=(
  "clouds   $STK/../tracks/lighthouse/dynamic_clouds.png"
  "mist     $COLOBOT/cloud02.png"
  "wisps    $COLOBOT/cloud04.png"
  "fire     $COLOBOT/cloud05.png"
)

# Nineteen more, picked by helper-73 (issue 25's trial, 2026-12-03) from the same packages
# and never tuned on: ten game textures that already tile and nine photographs that do
# not. Like SOFT, only the 128x128 central square, to $OUT25F.
OUT25F=/tmp/peer25/fresh
FRESH=(
  "earth     $STK/cracked-earth-texture.jpg"
  "rust      $STK/stkt_rustedMetal_a.png"
  "rock      $STK/hd_rock_01_d.png"
  "stonewall $STK/HortonRockWall.jpg"
  "concrete  $STK/concrete2.png"
  "sky       $STK/sky.jpg"
  "paper     $STK/stk_generic_cardboard_a.png"
  "moss      $STK/grass_dark.jpg"
  "carpet    $STK/stktex_pupleCarpet_a.png"
  "sea       $STK/sea.jpg"
  "boards    $STK/city_concrete.png"
  "plates    $STK/metal_plates.png"
  "dirt      $ETR/dirt01.png"
  "snow      $ETR/snow01.png"
  "ice       $ETR/ice01.png"
  "tiles     $SH3D/stoneTiles.jpg"
  "drystone  $SH3D/stone2Wall.jpg"
  "overcast  $SH3D/veryCloudy.jpg"
  "water     $COLOBOT/water12.png"
)

[ -f "$PKG_NODE" ] || { echo "missing $PKG_NODE: build the package first" >&2; exit 1; }
command -v node >/dev/null || { echo "node not found" >&2; exit 1; }

# ---------------------------------------------------------------- download and extract
mkdir -p "$DEBS" "$PKGS"
if ! apt-cache policy sweethome3d 2>/dev/null | grep -c Candidate >/dev/null; then
  echo "apt lists look empty: running apt-get update" >&2
  apt-get update -qq
fi
used=()
for spec in "${PACKAGES[@]}"; do
  name=${spec%%=*} ver=${spec#*=}
  cand=$(apt-cache policy "$name" 2>/dev/null | awk '/Candidate:/ {print $2}')
  if [ -z "$cand" ] || [ "$cand" = "(none)" ]; then echo "skip $name: not in the apt sources"; continue; fi
  if ! ls "$DEBS/${name}_"*.deb >/dev/null 2>&1; then
    if apt-cache show "$name=$ver" >/dev/null 2>&1; then want="$name=$ver"
    else echo "warning: $name $ver is gone, taking $cand" >&2; want=$name; fi
    (cd "$DEBS" && apt-get download -qq "$want" 2>&1 | grep -v "^W: Download is performed unsandboxed" || true)
  fi
  deb=$(ls "$DEBS/${name}_"*.deb | head -n1)
  if [ ! -f "$PKGS/$name/.extracted" ]; then
    rm -rf "${PKGS:?}/$name"; mkdir -p "$PKGS/$name"
    dpkg-deb -x "$deb" "$PKGS/$name" && touch "$PKGS/$name/.extracted"
  fi
  used+=("$(basename "$deb")")
done
echo "packages: ${used[*]}"

if [ ! -f "$JAR/.extracted" ]; then
  jarfile=$PKGS/sweethome3d/usr/share/sweethome3d/sweethome3d.jar
  rm -rf "$JAR"; mkdir -p "$JAR"
  if command -v unzip >/dev/null; then unzip -qo "$jarfile" 'com/eteks/sweethome3d/io/resources/textures/*' -d "$JAR"
  else python3 -c 'import sys, zipfile; z = zipfile.ZipFile(sys.argv[1]); z.extractall(sys.argv[2], [n for n in z.namelist() if n.startswith("com/eteks/sweethome3d/io/resources/textures/")])' "$jarfile" "$JAR"; fi
  touch "$JAR/.extracted"
fi

# ---------------------------------------------------------------- convert, masks
mkdir -p "$OUT30" "$OUT25" "$OUT25S" "$OUT25F"
{ printf '%s\n' "${PICKS[@]}"; printf '%s soft\n' "${SOFT[@]}"; printf '%s fresh\n' "${FRESH[@]}"; } |
  PKG_NODE=$PKG_NODE OUT30=$OUT30 OUT25=$OUT25 OUT25S=$OUT25S OUT25F=$OUT25F node --input-type=module -e '
import { readFileSync, writeFileSync } from "node:fs";
import { createHash } from "node:crypto";
const ps = await import(process.env.PKG_NODE);
const { OUT30, OUT25, OUT25S, OUT25F } = process.env;
const LONG = 224, TILE = 128, MARGIN = 12;

// Separable resampling with a tent filter, widened by the shrink factor (antialiased).
const taps = (len, nlen) => Array.from({ length: nlen }, (_, o) => { // per output index: first source index, weights
  const scale = len / nlen, sup = Math.max(1, scale), c = (o + 0.5) * scale - 0.5;
  const lo = Math.max(0, Math.ceil(c - sup)), hi = Math.min(len - 1, Math.floor(c + sup)), w = [];
  for (let i = lo; i <= hi; i++) w.push(Math.max(0, 1 - Math.abs(i - c) / sup));
  const ws = w.reduce((a, b) => a + b, 0);
  return { lo, w: w.map((v) => v / ws) };
});
function resize1(src, sw, sh, dw, dh, ch) { // src Float64Array sw*sh*ch -> dw*dh*ch
  const tx = taps(sw, dw), ty = taps(sh, dh), h1 = new Float64Array(dw * sh * ch), out = new Float64Array(dw * dh * ch);
  for (let y = 0; y < sh; y++) for (let x = 0; x < dw; x++) for (let k = 0; k < ch; k++) {
    let s = 0; tx[x].w.forEach((w, j) => { s += w * src[(y * sw + tx[x].lo + j) * ch + k]; }); h1[(y * dw + x) * ch + k] = s;
  }
  for (let y = 0; y < dh; y++) for (let x = 0; x < dw; x++) for (let k = 0; k < ch; k++) {
    let s = 0; ty[y].w.forEach((w, j) => { s += w * h1[((ty[y].lo + j) * dw + x) * ch + k]; }); out[(y * dw + x) * ch + k] = s;
  }
  return out;
}
function cropScale(img, x0, y0, cw, chh, dw, dh) {
  const f = new Float64Array(cw * chh * 3);
  for (let y = 0; y < chh; y++) for (let x = 0; x < cw; x++) for (let k = 0; k < 3; k++) f[(y * cw + x) * 3 + k] = img.data[4 * ((y0 + y) * img.width + x0 + x) + k];
  const r = resize1(f, cw, chh, dw, dh, 3), data = new Uint8ClampedArray(dw * dh * 4);
  for (let i = 0; i < dw * dh; i++) { for (let k = 0; k < 3; k++) data[4 * i + k] = Math.round(r[3 * i + k]); data[4 * i + 3] = 255; }
  return { width: dw, height: dh, data };
}

// Seeded blob: union of 3-4 ellipses, scaled to the target share, shifted inside the margin.
const fnv = (s) => { let h = 0x811c9dc5; for (const c of Buffer.from(s)) { h ^= c; h = Math.imul(h, 0x01000193) >>> 0; } return h; };
const mulberry = (a) => () => { a = (a + 0x6d2b79f5) >>> 0; let t = a; t = Math.imul(t ^ (t >>> 15), t | 1); t ^= t + Math.imul(t ^ (t >>> 7), t | 61); return ((t ^ (t >>> 14)) >>> 0) / 4294967296; };
function hole(name, W, H) {
  const rnd = mulberry(fnv(name));
  const n = rnd() < 0.5 ? 3 : 4, shapes = [];
  for (let k = 0; k < n; k++) {
    const th = rnd() * Math.PI;
    if (k === 0) { shapes.push({ ex: 0, ey: 0, rx: 1, ry: 0.6 + 0.4 * rnd(), th }); continue; }
    const phi = rnd() * 2 * Math.PI, d = 0.5 + 0.5 * rnd(), rx = 0.45 + 0.45 * rnd(), ry = rx * (0.55 + 0.45 * rnd());
    shapes.push({ ex: d * Math.cos(phi), ey: d * Math.sin(phi), rx, ry, th });
  }
  const target = 0.085 + 0.02 * rnd();
  const cx = W / 2 + (rnd() - 0.5) * 0.3 * W, cy = H / 2 + (rnd() - 0.5) * 0.3 * H;
  const draw = (s) => {
    const m = new Uint8Array(W * H);
    for (const e of shapes) {
      const c = Math.cos(e.th), sn = Math.sin(e.th), ax = e.rx * s, ay = e.ry * s, ox = cx + e.ex * s, oy = cy + e.ey * s;
      for (let y = 0; y < H; y++) for (let x = 0; x < W; x++) {
        const u = x + 0.5 - ox, v = y + 0.5 - oy, a = (u * c + v * sn) / ax, b = (-u * sn + v * c) / ay;
        if (a * a + b * b <= 1) m[y * W + x] = 1;
      }
    }
    return m;
  };
  const area = (m) => m.reduce((a, b) => a + b, 0) / (W * H);
  let lo = 1, hi = Math.max(W, H);
  for (let it = 0; it < 40; it++) { const mid = (lo + hi) / 2; if (area(draw(mid)) < target) lo = mid; else hi = mid; }
  let m = draw((lo + hi) / 2);
  // shift by whole pixels so the blob keeps MARGIN px from every border (area unchanged)
  let x0 = W, x1 = -1, y0 = H, y1 = -1;
  for (let y = 0; y < H; y++) for (let x = 0; x < W; x++) if (m[y * W + x]) { x0 = Math.min(x0, x); x1 = Math.max(x1, x); y0 = Math.min(y0, y); y1 = Math.max(y1, y); }
  if (x1 - x0 + 1 > W - 2 * MARGIN || y1 - y0 + 1 > H - 2 * MARGIN) throw new Error(`${name}: hole too wide for the margin`);
  const dx = Math.max(MARGIN - x0, 0) + Math.min(W - 1 - MARGIN - x1, 0), dy = Math.max(MARGIN - y0, 0) + Math.min(H - 1 - MARGIN - y1, 0);
  if (dx || dy) { const s = m; m = new Uint8Array(W * H); for (let y = 0; y < H; y++) for (let x = 0; x < W; x++) if (s[y * W + x]) m[(y + dy) * W + x + dx] = 1; }
  const share = area(m);
  if (share < 0.08 || share > 0.11) throw new Error(`${name}: hole share ${share}`);
  const margin = Math.min(x0 + dx, y0 + dy, W - 1 - (x1 + dx), H - 1 - (y1 + dy));
  return { m, share, n, margin };
}

const sha = (b) => createHash("sha256").update(b).digest("hex").slice(0, 12);
const lines = readFileSync(0, "utf8").trim().split("\n");
console.log("name     source                                            src size   out      hole  ellipses margin sha(png/hole)");
for (const line of lines) {
  const [name, path, soft] = line.trim().split(/\s+/);
  const bytes = readFileSync(path), img = ps.decodeImage(bytes);
  const cw = Math.round(img.width * 0.85), chh = Math.round(img.height * 0.85);
  const x0 = (img.width - cw) >> 1, y0 = (img.height - chh) >> 1;
  const k = LONG / Math.max(cw, chh), dw = Math.round(cw * k), dh = Math.round(chh * k);
  const out = cropScale(img, x0, y0, cw, chh, dw, dh);
  const s = Math.min(cw, chh);
  const tile = cropScale(img, x0 + ((cw - s) >> 1), y0 + ((chh - s) >> 1), s, s, TILE, TILE);
  if (soft) {
    const tilePng = ps.encodePng(tile);
    writeFileSync(`${soft === "fresh" ? OUT25F : OUT25S}/${name}.png`, tilePng);
    console.log(`${name.padEnd(8)} ${path.replace(/^.*\/(games|data|resources)\//, "").padEnd(49)} ${(img.width + "x" + img.height).padEnd(10)} ${soft}: 128x128 only ${sha(tilePng)}`);
    continue;
  }
  const { m, share, n, margin } = hole(name, dw, dh);
  const hd = new Uint8ClampedArray(dw * dh * 4);
  for (let i = 0; i < dw * dh; i++) { const v = m[i] ? 255 : 0; hd[4 * i] = hd[4 * i + 1] = hd[4 * i + 2] = v; hd[4 * i + 3] = 255; }
  const png = ps.encodePng(out), holePng = ps.encodePng({ width: dw, height: dh, data: hd }), tilePng = ps.encodePng(tile);
  writeFileSync(`${OUT30}/${name}.png`, png);
  writeFileSync(`${OUT30}/${name}.hole.png`, holePng);
  writeFileSync(`${OUT25}/${name}.png`, tilePng);
  const short = path.replace(/^\/tmp\/heldout\/(pkgs\/|jar\/)/, "").replace(/usr\/share\/games\/[^/]+\/(data\/)?|com\/eteks\/sweethome3d\/io\/resources\//, "").replace(/^textures\//, "sweethome3d.jar:textures/");
  console.log(`${name.padEnd(8)} ${short.padEnd(49)} ${(img.width + "x" + img.height).padEnd(10)} ${(dw + "x" + dh).padEnd(8)} ${(100 * share).toFixed(1).padStart(4)}% ${String(n).padStart(5)} ${String(margin).padStart(8)}   ${sha(png)}/${sha(holePng)}`);
}
const soft = lines.filter((l) => l.trim().endsWith(" soft")).length, fresh = lines.filter((l) => l.trim().endsWith(" fresh")).length;
const n = lines.length - soft - fresh;
console.log(`wrote ${n} x (NAME.png, NAME.hole.png) to ${OUT30}, ${n} x NAME.png (128x128) to ${OUT25}, ${soft} soft ones to ${OUT25S}, ${fresh} fresh ones to ${OUT25F}`);
'
