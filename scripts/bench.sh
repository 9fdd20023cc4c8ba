#!/usr/bin/env bash
# Benchmarks (figures, not pass/fail): native vs wasm-in-Node, medians of runs.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh >/dev/null
cargo build --release --example bench_vector --example bench_texture --example tune_texture --example bench_seamless -q
echo "== vector strokes"
node bench/vector.mjs
echo
echo "== textures"
node bench/texture.mjs
echo
echo "== seamless tiles"
node bench/seamless.mjs
