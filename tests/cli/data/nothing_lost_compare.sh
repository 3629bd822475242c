#!/usr/bin/env bash
# Nothing lost: `eval` of two torus-cull binaries on the rows adversarial_rows.py writes,
# in f64 (--exact f64), f32 rays (--precision f32) and the certified f32 path
# (--exact f32), compared byte for byte with their exit codes (a member a binary refuses
# must be refused by both, in the same words). One line per member and mode; exits 1 if
# any differ.
#   tests/cli/data/nothing_lost_compare.sh OLD_BINARY NEW_BINARY OUT_DIR [PER_KIND]
set -uo pipefail
old=$1 new=$2 out=$3 per_kind=${4:-320}
here=$(dirname "$0")
python3 "$here/adversarial_rows.py" "$out/rows" "$per_kind" || exit 2
mkdir -p "$out/old" "$out/new"
differ=0 same=0
while IFS=$'\t' read -r name flags; do
    rows=$(($(wc -l < "$out/rows/$name.csv") - 1))
    for mode in "--exact f64" "--precision f32" "--exact f32"; do
        tag=$(echo "$mode" | tr -d ' -')
        for side in old new; do
            bin=$old; [ $side = new ] && bin=$new
            # shellcheck disable=SC2086
            "$bin" eval $flags $mode --rays "$out/rows/$name.csv" \
                > "$out/$side/$name.$tag.csv" 2> "$out/$side/$name.$tag.err"
            echo $? > "$out/$side/$name.$tag.rc"
        done
        if cmp -s "$out/old/$name.$tag.csv" "$out/new/$name.$tag.csv" \
            && cmp -s "$out/old/$name.$tag.rc" "$out/new/$name.$tag.rc" \
            && cmp -s "$out/old/$name.$tag.err" "$out/new/$name.$tag.err"; then
            echo "$name $mode: identical ($rows rows, exit $(cat "$out/new/$name.$tag.rc"))"
            same=$((same + 1))
        else
            echo "$name $mode: DIFFER (exit $(cat "$out/old/$name.$tag.rc") -> $(cat "$out/new/$name.$tag.rc"))"
            differ=$((differ + 1))
        fi
    done
done < "$out/rows/members.tsv"
echo "identical: $same, differ: $differ"
[ $differ -eq 0 ]
