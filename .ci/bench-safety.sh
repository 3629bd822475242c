#!/usr/bin/env bash
# `cargo bench` never corrupts or silently drops results:
# - criterion's own flags reach only the criterion harness (`--save-baseline` works);
# - a complete smoke run writes a complete file that records its preset and sizes;
# - a filtered run leaves the complete file alone and writes only what it measured, to a
#   `-partial` file marked `meta.partial`;
# - `--list` is quick and writes nothing;
# - bad TORUS_CULL_* values are clear errors (exit 2 from the harness), not panics;
# - the default file names of `cargo bench` presets and `torus-cull run` differ.
set -euo pipefail
cd "$(dirname "$0")/.."
tmp=$(mktemp -d)
# What the default-named runs below add to results/ is removed however the script ends.
before=$(ls results)
cleanup() {
  for f in $(ls results); do
    grep -qxF "$f" <<<"$before" || rm -f "results/$f"
  done
  rm -rf "$tmp"
}
trap cleanup EXIT
export CARGO_TERM_COLOR=never CRITERION_HOME="$tmp/criterion"

fail() { echo "bench-safety: $*" >&2; exit 1; }
# The torus-cull command: the binary CI's `cargo test` built (TORUS_CULL_BIN), or cargo run.
tc() {
  if [ -n "${TORUS_CULL_BIN:-}" ]; then "$TORUS_CULL_BIN" "$@"; else cargo run --release --quiet -- "$@"; fi
}
command -v python3 >/dev/null || fail "python3 is needed to read the results JSON"
json() { python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print($2)" "$1"; }

echo "-- [${SECONDS} s] a complete smoke run under its default name, with a criterion flag the libtest harnesses would reject"
# Its default name (results/<commit>-smoke.json) is checked below against `run`'s; the file
# then moves to the temporary directory, where the other checks use it.
TORUS_CULL_BENCH=smoke cargo bench --quiet -- --save-baseline ci >"$tmp/complete.log" 2>&1 \
  || { cat "$tmp/complete.log"; fail "cargo bench -- --save-baseline failed"; }
bench_file=$(sed -n 's/^wrote \(results\/[^ ]*\.json\)$/\1/p' "$tmp/complete.log")
[ -n "$bench_file" ] && [ -f "$bench_file" ] || { cat "$tmp/complete.log"; fail "the smoke bench named no file it wrote"; }
mv "$bench_file" "$tmp/complete.json"
[ "$(json "$tmp/complete.json" "d['meta']['partial']")" = False ] || fail "complete run marked partial"
[ "$(json "$tmp/complete.json" "d['meta']['preset']")" = smoke ] || fail "preset not recorded"
[ "$(json "$tmp/complete.json" "d['meta']['sizes']['timing_rays']")" = 256 ] || fail "batch size not recorded"
[ "$(json "$tmp/complete.json" "d['meta']['sizes']['rejection_rays']")" = 1000 ] || fail "sweep size not recorded"
for section in rejection timing bvh solver estimates ratio; do
  [ "$(json "$tmp/complete.json" "len(d['$section']) > 0")" = True ] || fail "no $section records"
done
tc compare "$tmp/complete.json" "$tmp/complete.json" --only-changes \
  | tail -n 1
sum=$(sha256sum "$tmp/complete.json")

echo "-- [${SECONDS} s] a filtered run: the complete file is untouched, a partial file holds what ran"
# Criterion's filter is a regex matched anywhere in the name: anchored, so that
# `batch_cull_ns-hole` is not selected too.
TORUS_CULL_BENCH=smoke TORUS_CULL_RESULTS="$tmp/complete.json" \
  cargo bench --quiet -- '^cull_ns-hole' >"$tmp/filtered.log" 2>&1 \
  || { cat "$tmp/filtered.log"; fail "filtered cargo bench failed"; }
[ "$(sha256sum "$tmp/complete.json")" = "$sum" ] || fail "a filtered run rewrote the complete file"
partial="$tmp/complete-partial.json"
[ -f "$partial" ] || fail "a filtered run wrote no partial file"
[ "$(json "$partial" "d['meta']['partial']")" = True ] || fail "partial file not marked partial"
[ "$(json "$partial" "len(d['rejection']) + len(d['bvh']) + len(d['solver'])")" = 0 ] \
  || fail "the partial file holds records that were not measured"
[ "$(json "$partial" "sorted(set(e['benchmark'].split('/')[0] for e in d['estimates']))")" = "['cull_ns-hole']" ] \
  || fail "the partial file does not hold exactly the filtered benchmarks"

echo "-- [${SECONDS} s] --list: names only, quick, nothing written (default preset: its setup takes minutes)"
start=$SECONDS
TORUS_CULL_RESULTS="$tmp/complete.json" cargo bench --quiet -- --list >"$tmp/list.log" 2>&1 \
  || { cat "$tmp/list.log"; fail "cargo bench -- --list failed"; }
[ $((SECONDS - start)) -lt 30 ] || fail "--list took $((SECONDS - start)) s"
grep -q "^total_ns-hole/skala/2: benchmark$" "$tmp/list.log" || fail "--list printed no benchmark names"
[ "$(sha256sum "$tmp/complete.json")" = "$sum" ] || fail "--list rewrote the results file"
[ "$(find "$tmp" -maxdepth 1 -name '*.json' | wc -l)" = 2 ] || fail "--list wrote a file"

echo "-- [${SECONDS} s] bad environment values are named errors"
check_error() { # VAR=VALUE expected-text
  local log="$tmp/env.log"
  if env "$1" cargo bench --quiet >"$log" 2>&1; then fail "$1 was accepted"; fi
  grep -q "exit status: 2" "$log" || { cat "$log"; fail "$1: the harness did not exit 2"; }
  grep -qF "$2" "$log" || { cat "$log"; fail "$1: no '$2' in the error"; }
  if grep -q "panicked" "$log"; then cat "$log"; fail "$1 panicked"; fi
}
check_error TORUS_CULL_BENCH=fast 'TORUS_CULL_BENCH="fast" is invalid (allowed: smoke, default, full)'
check_error TORUS_CULL_BENCH_NU=5 '"5" is not a nu of workload default'
check_error TORUS_CULL_BENCH_NU=x '"x" is not a nu of workload default'
check_error TORUS_CULL_WORKLOAD=/no/such.json 'TORUS_CULL_WORKLOAD: workload /no/such.json'
printf '{"name":"w","seed":1,"cases":["hole"],"nu":[0.5],"rays":10}' >"$tmp/bad.json"
check_error TORUS_CULL_WORKLOAD="$tmp/bad.json" 'field `nu[0]`'
check_error TORUS_CULL_RESULTS="$tmp/complete.json/x.json" 'TORUS_CULL_RESULTS'
# A directory, or a file in a directory that does not exist: refused before the run, not
# after it (no mkdir -p).
check_error TORUS_CULL_RESULTS="$tmp" 'is a directory'
check_error TORUS_CULL_RESULTS="$tmp/no/such/r.json" 'does not exist'

echo "-- [${SECONDS} s] default names: a smoke bench and run never share a file"
tc run --workload workloads/quick.json --no-plots >"$tmp/run.log" 2>&1 \
  || { cat "$tmp/run.log"; fail "run failed"; }
run_file=$(sed -n 's/^wrote \(results\/[^ ]*\.json\)$/\1/p' "$tmp/run.log")
case "$bench_file" in results/*-smoke.json) ;; *) fail "smoke bench wrote '$bench_file'" ;; esac
case "$run_file" in results/*-quick-run.json) ;; *) fail "run wrote '$run_file'" ;; esac
echo "bench-safety: ok"
