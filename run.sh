#!/usr/bin/env bash
# The main command. Until the playground (issue 4) exists, it demonstrates the core on the paper's Table 1
# workload: Natural Earth land (59,212 vertices) against growing grids of squares, every operation, with the
# result areas, crossings and times, and writes the GeoJSON results to target/table1/.
set -euo pipefail
cd "$(dirname "$0")"
cargo build --quiet --release --example boolean
mkdir -p target/table1
for n in 8 162 974 3895; do
  ./target/release/examples/boolean intersection tests/data/land-50m.json.gz "tests/data/squares-$n.json.gz" \
    > "target/table1/intersection-$n.geojson"
done
for op in union difference xor; do
  ./target/release/examples/boolean "$op" tests/data/land-50m.json.gz tests/data/squares-3895.json.gz \
    > "target/table1/$op-3895.geojson"
done
echo "results written to target/table1/"
