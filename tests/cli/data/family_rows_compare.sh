#!/usr/bin/env bash
# Runs `eval` of two torus-cull binaries on the rows family_rows.py wrote (f64 and f32
# precision) and compares the outputs byte for byte; prints one line per file.
#   tests/cli/data/family_rows_compare.sh OLD_BINARY NEW_BINARY OUT_DIR
set -euo pipefail
old=$1 new=$2 out=$3
here=$(dirname "$0")/family_rows
mkdir -p "$out/old" "$out/new"
for f in "$here"/*.csv; do
    n=$(basename "$f" .csv)
    IFS=_ read -r big a b <<< "$n"
    for p in f64 f32; do
        "$old" eval --major "$big" --minor "$a" --axial "$b" --rays "$f" --precision "$p" > "$out/old/$n.$p.csv"
        "$new" eval --major "$big" --minor "$a" --axial "$b" --rays "$f" --precision "$p" > "$out/new/$n.$p.csv"
        if cmp -s "$out/old/$n.$p.csv" "$out/new/$n.$p.csv"; then
            echo "$n $p: identical"
        else
            echo "$n $p: differ"
        fi
    done
done
