#!/usr/bin/env bash
# The whole GPU measurement in one go, for a machine with a GPU but no Rust toolchain and
# no network (docs/gpu.md, "Measuring on a real GPU"): it takes a prebuilt, stripped
# `--features gpu` release binary and runs, within a wall-clock budget (default 540 s: one
# device command of at most 10 minutes, timeout_s 590, in a 15-minute lease with its start):
#
#   0. checks: the binary runs; the Vulkan loader (libvulkan.so.1) is there; wgpu finds an
#      adapter (`torus-cull gpu-info`: name, device type, backend, driver, SHADER_F64, the
#      f64 finish pass, timestamps). Missing loader or adapter: one line, exit 3 or 4. A
#      software adapter (lavapipe, device type Cpu) is refused outside --smoke (exit 5)
#      unless --allow-software: its figures are a CPU's.
#   1. bvh:    `time gpu-bvh`, the GPU BVH: every GPU cull at
#              the leaves over none, closest hit (10^6 camera rays) and any hit (a shadow
#              ray per hit), the five scene layouts at nu = 4 with 1 000 tori, 5 runs,
#              the copy kernel over the same ray bytes  -> bvh.json, bvh.txt
#              (not yet run on a GPU: sized from lavapipe and the H100's grid, below)
#   1b. subm:  `time gpu-submissions`, the single-torus
#              kernel's submissions one by one (issue 60, item 3): wall and device time
#              of each, at 2^20, 2^20 - 64, 2^20 + 64 and 2^21 ... 2^26 uniform rays (nu = 4),
#              the copy kernel, none and discriminant, 10 submissions each, rotated
#              -> subm.json, subm-submissions.csv, subm.txt (not yet run on a GPU)
#   2. grid:   `time gpu`, every GPU cull × case × ν of the workload, 10^6 rays
#              per case × ν                                   -> grid.json, grid.txt
#   3. sweep:  batch sizes 2^16 ... 2^22, culls none, cychosz, skala, discriminant, cases
#              uniform and hole, ν = 4                         -> sweep-2pK.json, .txt
#   3b. workgroup: the sweep's culls and cases at 10^6 rays with the kernel's workgroup
#              32, 128 and 256 (`--workgroup`; 64: the grid)
#                                                              -> wg-N.json, .txt
#   4. finish: `time gpu --finish`, the f64 finish pass after the kernel, on the
#              escalating cases (hole, grazing) at the workload's smallest ν, 4 and its
#              largest, culls none, cychosz, skala, 10^6 rays  -> finish.json, finish.txt
#              (skipped, and said so, where the adapter has no SHADER_F64)
#
# Every file is written under a temporary name and renamed when complete (the JSON files
# by torus-cull itself); summary.log is summary.log.partial until the script ends (a run
# killed from outside leaves the .partial, never a file that looks finished). A step that
# fails or runs out of budget is logged and the next step still runs; the exit code is
# then 1. Where $OUT is set (the device machine returns at most 8 files from it), the
# results folder is also packed into $OUT/gpu-device.tar.gz after every step, and the log
# copied to $OUT/summary.log(.partial): what a killed run had finished still comes back.
#
#   bash benches/gpu_device.sh [--smoke] [--bin PATH] [--workload FILE|default|quick]
#                              [--out DIR] [--budget SECONDS] [--allow-software]
#                              [--debs DIR] [--steps LIST]
#
#   --bin       the binary (default $TORUS_CULL_BIN, else target/release/torus-cull, else
#               .gpubin/torus-cull, where docs/gpu.md has it carried)
#   --workload  default: the binary's embedded `default` (5 cases x 12 nu, seed 20261121);
#               it must have nu = 4 and the cases hole, uniform, grazing
#   --out       results folder (default results/gpu-device-<UTC time>; where $OUT is
#               set, /tmp/gpu-device-<UTC time>, packed into $OUT as above)
#   --budget    wall-clock seconds for the whole run (default 540; --smoke: 240)
#   --smoke     every step at tiny sizes (under a minute on lavapipe): checks the script
#   --steps     the steps to run, comma-separated, of bvh,subm,grid,sweep,wg,finish,rest (default
#               all; a later session that has the first run's figures picks the rest)
#   --debs      where no libvulkan.so.1 is installed and this runs as root: the folder of
#               Debian packages (libvulkan1_*.deb and friends) to unpack into / first
#               (default .gl, as the device machine's README has it)
#   env WGPU_BACKEND (default vulkan), VK_DRIVER_FILES (set to the NVIDIA driver's ICD
#   under /usr/local/nvidia where the loader would not find it), SCALE (below).
#
# Sizing of --seconds (the `time` commands' paired-round time; each case x nu gets an
# equal share, and at least 7 rounds). Measured here, 2026-11-27, on lavapipe (llvmpipe,
# LLVM 15.0.6, Mesa 22.3.6; 2 cores of a Xeon shared with other builds, load 6-9):
#   - `torus-cull gpu-info` (process, adapter, device, kernel and f64 pass compiled): 1.4 s
#   - drawing the rays: the grazing generator is the slow one, ~17 s for 2^20 rays on one
#     loaded core (~5 us/ray of a free core); uniform and hole are far cheaper
#   - packing and uploading: 250-450 ns/ray here (the H100's host, 2026-11-25: 59-123)
#   - the kernel on lavapipe: ~400-450 ns/ray at 2^20 rays, 4-8 us/ray at 2^12 (there
#     the dispatch dominates); `time gpu --cases uniform,grazing --nu 4 --culls
#     none --batch 2^20 --seconds 0.1` took 38 s in all
#   - the smoke run (every step at 2^10-2^12 rays): 27-32 s; 104 s beside a cargo build
# Measured on an H100 (2026-11-27, 16 host cores), which replaced the plan made here: one
# kernel pass over 2^20 rays is 0.13-0.56 ms, but each case x nu unit costs ~5 s more than
# its share (drawing 2^20 rays on one core, packing, uploading), and nu = 1.1 far more:
#   - the whole default grid at --seconds 150 did not fit 430 s (55 of 60 units done);
#     `--nu 1.1,4,32 --seconds 45` did not fit 140 s; `--nu 4,32 --seconds 20`: 52 s;
#   - one workgroup step (2 units, 2^20 rays, --seconds 8): 20 s;
#   - the finish step at nu = 4 only (2 units, --seconds 15): 28 s.
# The BVH step (first: issue 60's question), not yet run on a GPU: on lavapipe here, with
# 1 000 tori, preparing and uploading cost ~190 ns a camera ray and ~1 us a shadow ray
# (spawned: its own torus's record formed in f64), the kernel ~21 us a camera ray; on a
# GPU the setup dominates: per scene ~1 s to draw the rays and spawn the shadow rays on
# one core, ~1-2 s more per run to upload them afresh, and the answers' check (9 culls x 2
# kinds of rays read back once); 5 scenes x 5 runs + 40 s of rounds: about 100-150 s,
# capped at 180 s (--seconds and the cap scale with SCALE); the submissions log (1b) at 120 s.
# Hence the order: bvh (~120 s), subm (~60 s: drawing 2^26 rays on one core and uploading
# 2^27 rays in all), grid at nu = 4 and the largest (~50 s), sweep (~7 x 15 s), workgroup
# (~3 x 20 s), finish (~3 units a case, ~60 s): ~455 s, and the rest of the grid's nu last
# with what is left of 540 s. Steps that hit their caps leave the last steps less or none. Every command runs under `timeout` with what is left of the budget, so
# the script ends within it whatever the GPU does; the summary log has each step's time.
# Scale: SCALE=0.5 halves every --seconds (not the batches), e.g. for a shorter lease.
#
set -uo pipefail
cd "$(dirname "$0")/.." || exit 2

bin=${TORUS_CULL_BIN:-target/release/torus-cull}
# The carried binary (docs/gpu.md) where there is no target/ (the device machine).
[ -n "${TORUS_CULL_BIN:-}" ] || [ -e "$bin" ] || bin=.gpubin/torus-cull
workload=default
out=""
smoke=0
budget=""
allow_software=0
debs=.gl
steps=bvh,subm,grid,sweep,wg,finish,rest
while [ $# -gt 0 ]; do
  case "$1" in
    --bin) bin=$2; shift 2 ;;
    --workload) workload=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --budget) budget=$2; shift 2 ;;
    --smoke) smoke=1; shift ;;
    --allow-software) allow_software=1; shift ;;
    --debs) debs=$2; shift 2 ;;
    --steps) steps=$2; shift 2 ;;
    -h|--help) sed -n '2,/^set -uo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    *) echo "gpu_device.sh: unknown argument $1 (see --help)" >&2; exit 2 ;;
  esac
done

if [ "$smoke" = 1 ]; then
  budget=${budget:-240}
  # Tiny: every step and every flag as in the real run, seconds of work on lavapipe.
  bvh_args=(--scenes ring_field,facing_grid --nu 4 --tori 24 --batch 256 --runs 2)
  bvh_seconds=0.6; bvh_cap=120
  subm_args=(--batches 4096,4032 --submissions 2); subm_cap=60
  grid_batch=4096; grid_seconds=4
  sweep_pows=(10 11 12); sweep_seconds=1
  wg_sizes=(32 256); wg_batch=4096
  finish_batch=4096; finish_seconds=2
else
  budget=${budget:-540}
  # 10^6 camera rays (a 1000 x 1000 image), not 2^20 (the H100's slow state, below).
  bvh_args=(--scenes ring_field,chain,facing_grid,mixed_nu,dense --nu 4 --tori 1000
    --batch 1000000 --runs 5)
  bvh_seconds=40; bvh_cap=180
  # Drawing 2^26 uniform rays on one core and uploading every batch (2^27 rays in all,
  # 60-120 ns a ray on the H100's host) is most of it.
  subm_args=(--submissions 10); subm_cap=120
  # 1 000 000 rays, not 2^20: on the H100 exactly 2^20 rays (and uniform rays at 2^21 and
  # 2^22) ran 3-5x slower than 2^20 +- 64, in a state the sweep keeps measuring
  # (docs/gpu.md, "Batch size on the H100").
  grid_batch=1000000; grid_seconds=20; rest_seconds=60
  sweep_pows=(16 17 18 19 20 21 22); sweep_seconds=8
  wg_sizes=(32 128 256); wg_batch=1000000
  finish_batch=1000000; finish_seconds=30
fi
for s in ${steps//,/ }; do
  case "$s" in bvh|subm|grid|sweep|wg|finish|rest) ;;
    *) echo "gpu_device.sh: --steps: unknown step $s (allowed: bvh, subm, grid, sweep, wg, finish, rest)" >&2; exit 2 ;;
  esac
done
# Whether step $1 was asked for.
wanted() { case ",$steps," in *",$1,"*) return 0 ;; *) return 1 ;; esac; }
scale=${SCALE:-1}
scaled() { awk -v s="$1" -v k="$scale" 'BEGIN { printf "%g", s * k }'; }
grid_seconds=$(scaled "$grid_seconds")
rest_seconds=$(scaled "${rest_seconds:-0}")
sweep_seconds=$(scaled "$sweep_seconds")
finish_seconds=$(scaled "$finish_seconds")
bvh_seconds=$(scaled "$bvh_seconds")
bvh_cap=$(scaled "$bvh_cap" | awk '{ printf "%d", $1 }')
subm_cap=$(scaled "$subm_cap" | awk '{ printf "%d", $1 }')

start=$(date +%s)
deadline=$((start + budget))
stamp=$(date -u +%Y%m%dT%H%M%SZ)
if [ -z "$out" ]; then
  if [ -n "${OUT:-}" ]; then
    out=${TMPDIR:-/tmp}/gpu-device-$stamp
  else
    out=results/gpu-device-$stamp
  fi
fi
mkdir -p "$out" || { echo "gpu_device.sh: cannot make $out" >&2; exit 2; }
log=$out/summary.log
partial=$log.partial
: > "$partial"
failed=0

say() { echo "$*" | tee -a "$partial" >&2; }
# Writes stdin to FILE through FILE.partial, renamed when complete.
write_file() { cat > "$1.partial" && mv -f "$1.partial" "$1"; }
# Where $OUT is set (the device machine, whose $OUT returns at most 8 files): the results
# folder as one archive, $OUT/gpu-device.tar.gz, remade after every step, and the log so
# far as $OUT/summary.log.partial (summary.log at the end). Each through a temp name.
publish() {
  [ -n "${OUT:-}" ] && [ -d "$OUT" ] || return 0
  local parent base
  parent=$(dirname "$out"); base=$(basename "$out")
  tar -czf "$OUT/.gpu-device.tar.gz.tmp" -C "$parent" --exclude='*.partial' "$base" \
    && mv -f "$OUT/.gpu-device.tar.gz.tmp" "$OUT/gpu-device.tar.gz"
  if [ -f "$log" ]; then
    cp "$log" "$OUT/.summary.log.tmp" && mv -f "$OUT/.summary.log.tmp" "$OUT/summary.log"
    rm -f "$OUT/summary.log.partial"
  else
    cp "$partial" "$OUT/.summary.log.tmp" && mv -f "$OUT/.summary.log.tmp" "$OUT/summary.log.partial"
  fi
}
# summary.log is renamed from its .partial when the script ends, however it ends (but a
# SIGKILL); the exit status of a failed check (2 to 5) is kept, a failed step makes it 1.
finish_log() {
  local code=$?
  [ "$code" != 0 ] || [ "$failed" = 0 ] || code=1
  echo "== end: $(date -u +%FT%TZ), $(( $(date +%s) - start )) s, exit $code" >> "$partial"
  mv -f "$partial" "$log"
  publish
  exit "$code"
}
trap finish_log EXIT
trap 'say "== interrupted"; exit 130' INT TERM HUP

# One line on stderr (and in the log), then exit CODE.
die() { say "gpu_device.sh: $2"; exit "$1"; }

say "== gpu_device.sh $([ "$smoke" = 1 ] && echo --smoke) $(date -u +%FT%TZ): binary $bin, workload $workload, budget ${budget} s, out $out"

# 0. Checks.
[ -x "$bin" ] || die 2 "no executable binary at $bin: build it with \`cargo build --release --features gpu --bin torus-cull\` (docs/gpu.md), or pass --bin"
version=$("$bin" --version 2>&1) || die 2 "$bin does not run: $version"
say "binary: $version, sha256 $(sha256sum "$bin" | cut -d' ' -f1)"

loader=""
if command -v ldconfig >/dev/null 2>&1; then
  loader=$(ldconfig -p 2>/dev/null | awk '/libvulkan\.so\.1 /{print $NF; exit}')
fi
if [ -z "$loader" ]; then
  for d in /usr/lib/x86_64-linux-gnu /usr/lib/aarch64-linux-gnu /usr/lib64 /usr/lib /usr/local/lib ${LD_LIBRARY_PATH//:/ }; do
    if [ -e "$d/libvulkan.so.1" ]; then loader=$d/libvulkan.so.1; break; fi
  done
fi
# The device machine's image has no loader: the session carries the Debian packages in
# .gl/ (docs/gpu.md; /work/.library/device/README.md) and, as root, they are unpacked here.
if [ -z "$loader" ] && [ -n "$debs" ] && ls "$debs"/libvulkan1_*.deb >/dev/null 2>&1 && [ "$(id -u)" = 0 ]; then
  for f in "$debs"/*.deb; do dpkg -x "$f" / || die 3 "cannot unpack $f"; done
  ldconfig
  loader=$(ldconfig -p 2>/dev/null | awk '/libvulkan\.so\.1 /{print $NF; exit}')
  say "unpacked $(ls "$debs"/*.deb | wc -l) packages from $debs into /: loader ${loader:-still missing}"
fi
[ -n "$loader" ] || die 3 "no Vulkan loader (libvulkan.so.1) on this machine: install libvulkan1, or carry its .deb in ${debs:-.gl}/ (docs/gpu.md)"
icds=$(ls /usr/share/vulkan/icd.d/ /etc/vulkan/icd.d/ 2>/dev/null | grep '\.json$' | tr '\n' ' ')
# The NVIDIA driver's ICD where the image mounts it outside the loader's search path.
nv_icd=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
if [ -z "${VK_DRIVER_FILES:-}${VK_ICD_FILENAMES:-}" ] && ! echo "$icds" | grep -q nvidia && [ -f "$nv_icd" ]; then
  export VK_DRIVER_FILES=$nv_icd
  icds="$icds(VK_DRIVER_FILES=$nv_icd)"
fi
say "vulkan loader: $loader; ICDs: ${icds:-none found}"
if command -v nvidia-smi >/dev/null 2>&1; then
  nvidia-smi --query-gpu=name,driver_version,memory.total,clocks.max.sm --format=csv,noheader 2>&1 \
    | sed 's/^/nvidia-smi: /' | tee -a "$partial" >&2
fi

# wgpu on Vulkan only: no silent fallback to GL (which would find llvmpipe through EGL).
export WGPU_BACKEND=${WGPU_BACKEND:-vulkan}
info=$("$bin" gpu-info 2> "$out/gpu-info.err")
code=$?
if [ $code -ne 0 ] && grep -q 'feature gpu' "$out/gpu-info.err"; then
  die 2 "$bin was built without the feature gpu: cargo build --release --features gpu --bin torus-cull"
fi
if [ $code -ne 0 ] && grep -q "unrecognized subcommand" "$out/gpu-info.err"; then
  die 2 "$bin has no gpu-info: build it from this commit (docs/gpu.md)"
fi
if [ $code -ne 0 ]; then
  die 4 "no GPU adapter (WGPU_BACKEND=$WGPU_BACKEND): $(tail -n 1 "$out/gpu-info.err")"
fi
rm -f "$out/gpu-info.err"
echo "$info" | write_file "$out/gpu-info.txt"
field() { echo "$info" | sed -n "s/^$1: //p"; }
say "adapter: $(field adapter) ($(field device_type), $(field backend), driver $(field driver)); shader_f64 $(field shader_f64); f64 finish pass $(field f64_finish_pass); timestamps $(field timestamps)"
if [ "$(field software)" = yes ]; then
  if [ "$smoke" = 0 ] && [ "$allow_software" = 0 ]; then
    die 5 "the adapter is a CPU rasteriser ($(field adapter)): no GPU to time; --smoke checks the script on it, --allow-software times it anyway"
  fi
  say "note: a software adapter: every figure below is this CPU's, no GPU speed"
fi

# The command a step runs (the BVH step sets its own, and a cap on its time).
step_cmd=(time gpu)
step_cap=""
# Flags every step takes but the submissions log (which draws no plots).
step_flags=(--no-plots)
# Runs one `torus-cull time gpu` step (or "${step_cmd[@]}") under what is left of
# the budget (at most $step_cap s where set): its JSON at NAME.json (torus-cull writes it
# through a temp name), its table at NAME.txt.
step() {
  local name=$1; shift
  local left=$((deadline - $(date +%s)))
  if [ -n "$step_cap" ] && [ "$left" -gt "$step_cap" ]; then left=$step_cap; fi
  if [ "$left" -lt 5 ]; then
    failed=1; say "== $name: skipped, the budget is spent"; return
  fi
  say "== $name: torus-cull ${step_cmd[*]} $* (timeout ${left} s)"
  local t0=$(date +%s)
  timeout --signal=TERM --kill-after=10 "$left" \
    "$bin" "${step_cmd[@]}" "${step_flags[@]}" --out "$out/$name.json" "$@" \
    > "$out/$name.txt.partial" 2> "$out/$name.err"
  local rc=$?
  local took=$(( $(date +%s) - t0 ))
  if [ $rc -eq 0 ]; then
    mv -f "$out/$name.txt.partial" "$out/$name.txt"
    rm -f "$out/$name.err"
    say "   $name: done in ${took} s"
  else
    failed=1
    mv -f "$out/$name.txt.partial" "$out/$name.failed.txt"
    if [ $rc -eq 124 ] || [ $rc -eq 137 ]; then
      say "   $name: FAILED, out of budget after ${took} s (no JSON written); its output so far: $out/$name.failed.txt"
    else
      say "   $name: FAILED (exit $rc) after ${took} s: $(tail -n 1 "$out/$name.err")"
    fi
  fi
  publish
}

# The workload's smallest and largest ν, for the finish step (from the file, or the
# embedded default's).
case "$workload" in
  default) wl_nu="1.1 1.25 1.5 2 3 4 6 8 12 16 24 32" ;;
  quick) wl_nu="1.1 2 8 32" ;;
  *) wl_nu=$(tr -d '\n' < "$workload" | sed -n 's/.*"nu" *: *\[\([^]]*\)\].*/\1/p' | head -n 1 | tr ',' ' ') ;;
esac
lo=$(echo $wl_nu | awk '{print $1}')
hi=$(echo $wl_nu | awk '{print $NF}')

# 1. The GPU BVH (not yet run on a GPU), under its cap so that the steps after it run.
if wanted bvh; then
  step_cmd=(time gpu-bvh); step_cap=$bvh_cap
  step bvh --workload "$workload" "${bvh_args[@]}" --seconds "$bvh_seconds"
  step_cmd=(time gpu); step_cap=""
fi

# 1b. Every submission of the single-torus kernel at 2^20, 2^20 +- 64 and up to 2^26 rays.
if wanted subm; then
  step_cmd=(time gpu-submissions); step_cap=$subm_cap; step_flags=()
  step subm --workload "$workload" --case uniform --nu 4 "${subm_args[@]}"
  step_cmd=(time gpu); step_cap=""; step_flags=(--no-plots)
fi

# 2. The grid, in two parts: ν = 4 and the largest first (what the headline needs, ~50 s
#    on the H100), the rest of the workload's ν last, with what the budget leaves (on the
#    H100 the whole default grid did not fit 430 s: 55 of its 60 units, see below).
grid_nu=$(printf '%s\n' 4 "$hi" | awk '!seen[$0]++' | paste -sd, -)
[ "$smoke" = 1 ] && grid_nu=4
wanted grid && step grid --workload "$workload" --batch "$grid_batch" --seconds "$grid_seconds" --nu "$grid_nu"

# 3. The batch sweep.
if ! echo " $wl_nu " | grep -q ' 4 '; then
  failed=1; say "== sweep: skipped, workload $workload has no nu = 4 (it has: $wl_nu)"
  sweep_pows=(); wg_sizes=()
fi
wanted sweep || sweep_pows=()
for p in "${sweep_pows[@]}"; do
  step "sweep-2p$p" --workload "$workload" --cases uniform,hole --nu 4 \
    --culls none,cychosz,skala,discriminant --batch $((1 << p)) --seconds "$sweep_seconds"
done

# 3b. The kernel's workgroup size (64: the grid): the same rays and culls at
#     10^6 rays, in one process per size (not paired across sizes: compare ns/ray and of_copy).
wanted wg || wg_sizes=()
for w in "${wg_sizes[@]}"; do
  step "wg-$w" --workload "$workload" --cases uniform,hole --nu 4 \
    --culls none,cychosz,skala,discriminant --batch "$wg_batch" --seconds "$sweep_seconds" \
    --workgroup "$w"
done

# 4. The f64 finish pass.
if ! wanted finish; then
  :
elif [ "$(field f64_finish_pass)" = yes ]; then
  finish_nu=$(printf '%s\n' "$lo" 4 "$hi" | awk '!seen[$0]++' | paste -sd, -)
  [ "$smoke" = 1 ] && finish_nu=4
  step finish --finish --workload "$workload" --cases hole,grazing --nu "$finish_nu" \
    --culls none,cychosz,skala --batch "$finish_batch" --seconds "$finish_seconds"
else
  say "== finish: skipped, the adapter has no f64 finish pass ($(field f64_finish_pass))"
fi

# 5. The rest of the grid's ν, with what is left.
if [ "$smoke" = 0 ] && wanted rest; then
  rest=$(printf '%s\n' $wl_nu | awk -v hi="$hi" '$1 != 4 && $1 != hi' | paste -sd, -)
  [ -z "$rest" ] || step grid-rest --workload "$workload" --batch "$grid_batch" \
    --seconds "$rest_seconds" --nu "$rest"
fi

# The headline lines, in the log and on stderr.
if [ -f "$out/bvh.txt" ]; then
  say "== bvh, closest hit per scene/nu (ns/ray): none (Mrays/s), the fastest cull, the copy kernel:"
  awk '/^gpu_bvh_closest_ns:/ { on = 1; next } /^gpu_bvh_anyhit_ns:/ { on = 0 }
       on && $2 != "copy" && $4 ~ /^[0-9.]+$/ {
         k = $1 "/" $2; if ($3 == "none") { none[k] = $4; mr[k] = $5 }
         if (!(k in best) || $4 < best[k]) { best[k] = $4; who[k] = $3 }
         if (!(k in seen)) { seen[k] = 1; order[++n] = k } }
       on && $2 == "copy" { copy[$1] = $3 }
       END { for (i = 1; i <= n; i++) { k = order[i]; printf "   %-16s none %s (%s Mrays/s), fastest %s %s, copy %s\n", k, none[k], mr[k], who[k], best[k], copy[k] } }' \
    "$out/bvh.txt" | tee -a "$partial" >&2
fi
if [ -f "$out/grid.txt" ]; then
  gmax=$(awk '$4 ~ /^[0-9.]+$/ && $2 + 0 > m { m = $2 + 0 } END { print m }' "$out/grid.txt")
  say "== grid at nu = $gmax, per case: none, and the fastest cull (ns/ray):"
  awk -v nu="$gmax" '$2 + 0 == nu && $3 != "copy" && $4 ~ /^[0-9.]+$/ { print $1, $3, $4 }' "$out/grid.txt" \
    | awk '{ if ($2 == "none") none[$1] = $3; if (!($1 in best) || $3 < best[$1]) { best[$1] = $3; who[$1] = $2 }; if (!($1 in seen)) { seen[$1] = 1; order[++n] = $1 } }
           END { for (i = 1; i <= n; i++) { c = order[i]; printf "   %-11s none %s, fastest %s %s\n", c, none[c], who[c], best[c] } }' \
    | tee -a "$partial" >&2
fi
for f in "$out"/sweep-2p*.txt "$out"/wg-*.txt; do
  [ -f "$f" ] || continue
  awk -v f="$(basename "$f" .txt)" '$3 == "none" && $4 ~ /^[0-9.]+$/ { print "   " f ": " $1 " none " $4 " ns/ray" }' "$f" \
    | tee -a "$partial" >&2
done
if [ -f "$out/subm.txt" ]; then
  say "== subm: per batch and contender, the median, fastest and slowest pass (ns/ray) and wall ms a submission:"
  awk '$1 ~ /^[0-9]+$/' "$out/subm.txt" | sed 's/^/   /' | tee -a "$partial" >&2
fi
if [ -f "$out/finish.txt" ]; then
  grep 'f64 finish pass' "$out/finish.txt" | sed 's/^/   /' | tee -a "$partial" >&2
fi
say "== files in $out: $(cd "$out" && ls | grep -v '\.partial$' | tr '\n' ' ')"
