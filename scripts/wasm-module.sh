#!/usr/bin/env bash
# Builds one wasm module of the crate: bash scripts/wasm-module.sh NAME FEATURES SIMD OPT OUT
#   NAME      file names in OUT: NAME.js (wasm-bindgen's web glue, patched) and NAME_bg.wasm
#   FEATURES  Cargo features (engines) the module holds, e.g. vector,texture
#   SIMD      1: built with simd128 (its own target dir, so neither build undoes the
#             other's incremental state); 0: scalar, for engines without SIMD
#   OPT       wasm-opt's level: Oz (size) or O3 (speed)
# wasm-opt's output is cached by its input's hash (target/wasm-opt/), so a build with
# nothing changed costs only Cargo's and wasm-bindgen's checks.
set -euo pipefail
cd "$(dirname "$0")/.."
name=$1 features=$2 simd=$3 opt=$4 out=$5
target=target
flags=${RUSTFLAGS:-}
if [ "$simd" = 1 ]; then
  target=target/simd
  flags="$flags -C target-feature=+simd128"
fi
RUSTFLAGS="$flags" CARGO_TARGET_DIR=$target \
  cargo build --release --target wasm32-unknown-unknown --lib --no-default-features --features "$features" -q
# The glue only: the package's own entries (js/pkg) wrap it and carry the types.
wasm-bindgen --target web --no-typescript --out-dir "$out" --out-name "$name" \
  "$target/wasm32-unknown-unknown/release/patternsynth.wasm"
node scripts/patch-glue.mjs "$out/$name.js"
# npm's binaryen (Debian's wasm-opt 108 emits modules that fail to load).
mkdir -p target/wasm-opt
extra=()
[ "$simd" = 1 ] && extra=(--enable-simd)
flags_opt=("-$opt" --converge --strip-debug --strip-producers --enable-bulk-memory --enable-nontrapping-float-to-int
  --enable-sign-ext --enable-mutable-globals --enable-reference-types --enable-multivalue "${extra[@]}")
# The cache key: the input, every flag and wasm-opt's version.
key=$( (sha256sum "$out/${name}_bg.wasm" | cut -d' ' -f1; echo "${flags_opt[*]}"; node_modules/.bin/wasm-opt --version) | sha256sum | cut -c1-32)
cached=target/wasm-opt/$key.wasm
if [ ! -f "$cached" ]; then
  node_modules/.bin/wasm-opt "${flags_opt[@]}" "$out/${name}_bg.wasm" -o "$cached.part"
  mv "$cached.part" "$cached"
fi
cp "$cached" "$out/${name}_bg.wasm"
