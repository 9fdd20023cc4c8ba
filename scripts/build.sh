#!/usr/bin/env bash
# Builds the npm package into pkg/ (and a copy for the playground in www/pkg/).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh

cargo build --release --target wasm32-unknown-unknown --lib
rm -rf pkg && mkdir -p pkg/wasm
# The glue only: the package's own entries (js/pkg) wrap it and carry the types.
wasm-bindgen --target web --no-typescript --out-dir pkg/wasm --out-name full \
  target/wasm32-unknown-unknown/release/patternsynth.wasm
node scripts/patch-glue.mjs pkg/wasm/full.js
# npm's binaryen (Debian's wasm-opt 108 emits modules that fail to load).
node_modules/.bin/wasm-opt -Oz --converge --strip-debug --strip-producers --enable-bulk-memory --enable-nontrapping-float-to-int --enable-sign-ext \
  --enable-mutable-globals --enable-reference-types --enable-multivalue \
  pkg/wasm/full_bg.wasm -o pkg/wasm/full_bg.wasm
cp js/pkg/* LICENSE-MIT LICENSE-APACHE pkg/
rm -f pkg/.gitignore
rm -rf www/pkg && cp -r pkg www/pkg
# The playground's built-in textures: the CC0 photographs the tests use.
mkdir -p www/textures && cp tests/fixtures/textures/*.png www/textures/
raw=$(stat -c %s pkg/wasm/full_bg.wasm)
gz=$(gzip -9 -c pkg/wasm/full_bg.wasm | wc -c)
echo "pkg/wasm/full_bg.wasm: $raw bytes raw, $gz bytes gzip"
