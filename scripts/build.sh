#!/usr/bin/env bash
# Builds the npm package into pkg/ (and a copy for the playground in www/pkg/).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh

rm -rf pkg && mkdir -p pkg/wasm
# One wasm module per entry, each with only its engines (Cargo features), so a page
# pays for what it uses: full = vector + texture (the main entry), and each alone;
# the codecs (PNG/JPEG) are a module of their own that browsers need not load.
module() {
  local name=$1 features=$2
  cargo build --release --target wasm32-unknown-unknown --lib --no-default-features --features "$features"
  # The glue only: the package's own entries (js/pkg) wrap it and carry the types.
  wasm-bindgen --target web --no-typescript --out-dir pkg/wasm --out-name "$name" \
    target/wasm32-unknown-unknown/release/patternsynth.wasm
  node scripts/patch-glue.mjs "pkg/wasm/$name.js"
  # npm's binaryen (Debian's wasm-opt 108 emits modules that fail to load).
  node_modules/.bin/wasm-opt -Oz --converge --strip-debug --strip-producers --enable-bulk-memory \
    --enable-nontrapping-float-to-int --enable-sign-ext --enable-mutable-globals --enable-reference-types \
    --enable-multivalue "pkg/wasm/${name}_bg.wasm" -o "pkg/wasm/${name}_bg.wasm"
}
module full vector,texture
module vector vector
module texture texture
module codec codec
cp -r js/pkg/* LICENSE-MIT LICENSE-APACHE pkg/
# The Node entries carry their modules in JS (bundled servers have no .wasm beside them).
node scripts/embed-wasm.mjs pkg
node scripts/cts-types.mjs pkg
rm -f pkg/.gitignore
rm -rf www/pkg && cp -r pkg www/pkg
# The playground's built-in textures: the CC0 photographs the tests use.
mkdir -p www/textures && cp tests/fixtures/textures/*.png www/textures/
node scripts/sizes.mjs pkg/wasm
