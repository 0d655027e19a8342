#!/usr/bin/env bash
# The main command: builds the playground for the browser and serves it (index.html) on http://127.0.0.1:8080/
# (or $PORT). Needs Rust (rustup) and Node 18+; installs the wasm target and wasm-bindgen-cli itself.
set -euo pipefail
cd "$(dirname "$0")"
source web/tools.sh
web/build-playground.sh
exec node web/serve.mjs "${PORT:-8080}"
