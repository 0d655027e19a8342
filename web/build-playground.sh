#!/usr/bin/env bash
# Builds the playground (crates/polysweep-playground) for the browser into target/playground/, where index.html
# loads it from. Needs the tools of web/tools.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --profile playground --target wasm32-unknown-unknown -p polysweep-playground --lib
wasm-bindgen --target web --no-typescript --out-dir target/playground \
  target/wasm32-unknown-unknown/playground/polysweep_playground.wasm
cp crates/polysweep-playground/worker.js target/playground/worker.js
