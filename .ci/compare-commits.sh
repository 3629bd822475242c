#!/usr/bin/env bash
# The README's "Comparing commits" recipe, run line by line as written there, on a
# throwaway clone of HEAD where NEW commits the results file that OLD's bench would have
# written into the tree (the case that made `git checkout NEW` refuse), at the smoke size.
# Each results file must carry the commit its bench was built from.
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "compare-commits: $*" >&2; exit 1; }

recipe=$(awk '/^## Comparing commits/ {f = 1} f && /^```sh$/ {b = 1; next} b && /^```$/ {exit} b' \
  "$repo/README.md")
[ -n "$recipe" ] || fail "no sh block under '## Comparing commits' in README.md"

git clone --quiet "$repo" "$tmp/clone"
cd "$tmp/clone"
git config user.email ci@torus-cull.invalid
git config user.name ci
# The clone's own two crates at opt-level 1 (its dependencies keep the shared release
# builds): this recipe checks the commands and the files they write, at the smoke size, not
# speed, and its first build compiles both crates afresh at the clone's new path.
mkdir -p .cargo
printf '[profile.release.package.%s]\nopt-level = 1\n' torus-cull torus-cull-lab >.cargo/config.toml
old=$(git rev-parse --short HEAD)
mkdir -p results
echo '{}' >"results/$old.json"
git add "results/$old.json"
git commit --quiet -m "results of $old"
new=$(git rev-parse --short HEAD)

# Share the compiled dependencies, so only torus-cull itself is built, once per commit;
# incremental, so that NEW's build reuses most of OLD's.
export CARGO_TARGET_DIR="$repo/target" CRITERION_HOME="$tmp/criterion"
export TORUS_CULL_BENCH=smoke CARGO_TERM_COLOR=never CARGO_INCREMENTAL=1
status=0
while IFS= read -r line; do
  cmd=${line//OLD/$old}
  cmd=${cmd//NEW/$new}
  # `cargo run --release` would build the command again without the dev-dependencies'
  # features (about a minute); CI's `cargo test` built it from the same code as NEW
  # (NEW adds a results file only), so that binary runs the line instead.
  if [ -n "${TORUS_CULL_BIN:-}" ]; then
    cmd=${cmd//cargo run --release --/$TORUS_CULL_BIN}
  fi
  case "$cmd" in
    "echo \$?"*) echo "compare exited $status"; continue ;;
  esac
  echo "\$ $cmd   [${SECONDS} s]"
  set +e
  eval "$cmd" >"$tmp/step.log" 2>&1
  status=$?
  set -e
  case "$cmd" in
    *" compare "*) [ "$status" -le 1 ] || { cat "$tmp/step.log"; fail "compare exited $status"; } ;;
    *) [ "$status" -eq 0 ] || { cat "$tmp/step.log"; fail "'$cmd' exited $status"; } ;;
  esac
done <<<"$recipe"
grep -q "records compared" "$tmp/step.log" || { cat "$tmp/step.log"; fail "compare printed no summary"; }

for side in old new; do
  want=${!side}
  # Read as JSON (the files are compact, one line), not grepped.
  got=$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["meta"]["commit"])' \
    "$tmp/bench-compare/$side.json")
  [ "$got" = "$want" ] || fail "$side.json has meta.commit '$got', its bench was built at $want"
done
echo "compare-commits: ok (OLD $old, NEW $new)"
