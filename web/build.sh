#!/usr/bin/env bash
# Builds the npm package into pkg/: the core compiled to wasm, wasm-bindgen's glue, and the hand-written entry
# (web/src). Needs the wasm32 target, wasm-bindgen-cli 0.2.130 and the npm devDependencies (see ../test.sh, which
# installs them).
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --quiet --profile wasm --target wasm32-unknown-unknown -p polysweep-wasm
wasm-bindgen --target web --out-dir pkg --out-name polysweep_wasm \
  target/wasm32-unknown-unknown/wasm/polysweep_wasm.wasm
# binaryen 132 from npm: the only wasm-opt that reads current rustc output here.
node_modules/.bin/wasm-opt -O3 --enable-bulk-memory --enable-nontrapping-float-to-int --enable-sign-ext \
  --enable-mutable-globals pkg/polysweep_wasm_bg.wasm -o pkg/polysweep_wasm_bg.wasm
cp web/src/api.js web/src/polysweep.js web/src/polysweep.node.js web/src/polysweep.d.ts pkg/
