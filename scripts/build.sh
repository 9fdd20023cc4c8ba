#!/usr/bin/env bash
# Builds the npm package into pkg/ (and a copy for the playground in www/pkg/).
# Skipped when nothing it is made from changed since the last build (target/pkg.stamp).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh

# Everything the package is made from: a change to any of these builds it again.
stamp=$( (find src js/pkg tests/fixtures/textures scripts/build.sh scripts/wasm-module.sh scripts/patch-glue.mjs \
  scripts/embed-wasm.mjs scripts/cts-types.mjs scripts/sizes.mjs Cargo.toml Cargo.lock package-lock.json \
  LICENSE-MIT LICENSE-APACHE -type f -print0 | sort -z | xargs -0 sha256sum; echo "${RUSTFLAGS:-}"; rustc -V) | sha256sum | cut -c1-32)
built() { [ -f pkg/package.json ] && [ -f www/pkg/package.json ] && [ "$(ls pkg/wasm/*_bg.wasm 2>/dev/null | wc -l)" = 6 ] && [ -d www/textures ]; }
if [ -f target/pkg.stamp ] && [ "$(cat target/pkg.stamp)" = "$stamp" ] && built; then
  echo "pkg/ is up to date (nothing it is built from changed)."
  exit 0
fi
rm -f target/pkg.stamp
rm -rf pkg && mkdir -p pkg/wasm
# One wasm module per entry, each with only its engines (Cargo features), so a page
# pays for what it uses: full = vector + texture (the main entry), and each alone;
# the codecs (PNG/JPEG) are a module of their own that browsers need not load.
# Modules with the texture engine come twice: built with simd128 (NAME_bg.wasm, what
# every browser since 2023 and Node load) and without (NAME_scalar_bg.wasm, for the
# rest; js/pkg/simd.js decides at load). Both share one glue: it depends only on the
# exports, which SIMD does not change (checked below). The SIMD builds take wasm-opt
# -O3 (speed; bench/speed.mjs: 72 against 74 ms at 256², 1179 against 1204 at 1024², about
# level at 2048², for 0.7% more bytes), the others -Oz.
bash scripts/wasm-module.sh full vector,texture 1 O3 pkg/wasm
bash scripts/wasm-module.sh vector vector 0 Oz pkg/wasm
bash scripts/wasm-module.sh texture texture 1 O3 pkg/wasm
bash scripts/wasm-module.sh codec codec 0 Oz pkg/wasm
for module in "full vector,texture" "texture texture"; do
  set -- $module
  rm -rf target/scalar && bash scripts/wasm-module.sh "$1" "$2" 0 Oz target/scalar
  cmp -s "target/scalar/$1.js" "pkg/wasm/$1.js" || { echo "the scalar and SIMD builds of $1 have different glue" >&2; exit 1; }
  cp "target/scalar/$1_bg.wasm" "pkg/wasm/$1_scalar_bg.wasm"
done
cp -r js/pkg/* LICENSE-MIT LICENSE-APACHE pkg/
# The Node entries carry their modules in JS (bundled servers have no .wasm beside them).
node scripts/embed-wasm.mjs pkg
node scripts/cts-types.mjs pkg
rm -f pkg/.gitignore
rm -rf www/pkg && cp -r pkg www/pkg
# The playground's built-in textures: the CC0 photographs the tests use.
mkdir -p www/textures && cp tests/fixtures/textures/*.png www/textures/
node scripts/sizes.mjs pkg/wasm
echo "$stamp" > target/pkg.stamp
