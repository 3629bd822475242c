#!/usr/bin/env bash
# The honesty check of the paired intervals (docs/results.md, "Do the intervals hold?"):
# three `torus-cull time` runs on the quick workload, back to back, then
# `torus-cull intervals` over them: the share of each run's ratios that fall inside the
# other runs' intervals (goal >= 95 %) and the worst headline change (goal <= 3 %).
# A benchmark, not a test: run it on a quiet machine. Exits 1 when a goal is missed.
#
#   bash benches/honest_intervals.sh [DIR]     # keeps run1..3.json in DIR (default: a temp dir)
#   SECONDS_PER_RUN=30 RUNS=3 bash benches/honest_intervals.sh
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${SECONDS_PER_RUN:-30}
runs=${RUNS:-3}
dir=${1:-$(mktemp -d)}
mkdir -p "$dir"
cargo build --release --quiet --bin torus-cull
files=()
for k in $(seq 1 "$runs"); do
  echo "== run $k of $runs: torus-cull time --workload workloads/quick.json --seconds $seconds" >&2
  target/release/torus-cull time --workload workloads/quick.json --seconds "$seconds" \
    --no-plots --out "$dir/run$k.json" > /dev/null
  files+=("$dir/run$k.json")
done
echo "== the runs are in $dir" >&2
target/release/torus-cull intervals "${files[@]}"
