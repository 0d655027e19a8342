#!/usr/bin/env bash
# The benchmark (issue 5): the paper's Table 1 on real land data, native and wasm, every engine in one run, and the
# dense workloads (issue 25), written by the native benchmark to target/bench/dense/ and run there and in Node; the
# layer overlay (issue 26), which prints its own table; then the tables (docs/benchmarks.md) and the chart
# (docs/benchmarks.svg). Installs what it needs first, as test.sh does (the wasm target, wasm-bindgen-cli, the npm
# packages of the peers). Timings are medians of one run on this
# machine; nothing here asserts them.
set -euo pipefail
cd "$(dirname "$0")"
source web/tools.sh
npm install --no-audit --no-fund
cargo run --quiet --release -p polysweep-bench
web/build.sh
node web/bench/wasm.mjs
node web/bench/dense.mjs
# Lines and layers (issue 26): 10,000 parcels × 100 zones, polysweep's layer overlay beside GEOS per pair (shapely,
# in the venv web/python.sh makes) and turf's intersect in a loop; prints its own table, and target/bench/layers.json.
source web/python.sh
node web/bench/layers.mjs
node web/bench/report.mjs
