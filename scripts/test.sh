#!/usr/bin/env bash
# Runs every test: formatting and lints, the engines natively, the built package under
# Node, the playground end to end in headless Chromium, and the packed package in
# bundlers' production builds. Installs what it needs.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --browser

echo "== cargo fmt / clippy"
cargo fmt --check
cargo clippy --all-targets -- -D warnings
cargo clippy --target wasm32-unknown-unknown --lib -- -D warnings
RUSTFLAGS='-C target-feature=+simd128' CARGO_TARGET_DIR=target/simd cargo clippy --target wasm32-unknown-unknown --lib -- -D warnings

echo "== native engine tests"
cargo test --release

echo "== package build"
bash scripts/build.sh

# Every test has 5 minutes (the slowest takes about 12 s): one that never settles fails
# instead of holding the run to CI's limit.
echo "== JS API under Node"
node --test --test-timeout=300000 tests/node/

echo "== playground in headless Chromium"
mkdir -p out
node --test --test-timeout=300000 tests/browser/

echo "== the packed package in Vite, webpack and esbuild production builds, and tsc --strict"
node --test --test-timeout=300000 tests/bundlers/

echo "== the packed package in Next.js 16 (Turbopack) and 15, SvelteKit (adapter-node), Astro (Node adapter), Parcel and Rollup"
node --test --test-timeout=900000 tests/frameworks/
