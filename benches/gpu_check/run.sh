#!/usr/bin/env bash
# The GPU correctness check on a lent machine (docs/gpu.md, "Every cull on an NVIDIA H100"):
# every ray file .gpucheck/rays-R-r.csv.gz (made here by benches/gpu_check/make_rays.py,
# gzipped, carried with .gpubin and .gl) through the kernel with `eval --exact gpu`; the
# outputs packed into $OUT/gpu-check.tar.gz, to compare here with `eval --exact f32`.
set -u
cd "$(dirname "$0")/../.." || exit 2
mkdir -p /tmp/gpucheck
export WGPU_BACKEND=${WGPU_BACKEND:-vulkan}
nv=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
if [ -z "${VK_DRIVER_FILES:-}" ] && ! ls /usr/share/vulkan/icd.d /etc/vulkan/icd.d 2>/dev/null | grep -q nvidia && [ -f "$nv" ]; then
  export VK_DRIVER_FILES=$nv
fi
.gpubin/torus-cull gpu-info > /tmp/gpucheck/gpu-info.txt 2>&1; echo "gpu-info: exit $?"
for f in .gpucheck/rays-*.csv.gz; do
  b=$(basename "$f" .csv.gz); spec=${b#rays-}; R=${spec%-*}; r=${spec#*-}
  zcat "$f" | timeout 60 .gpubin/torus-cull eval --major "$R" --minor "$r" --rays - --exact gpu --out /tmp/gpucheck/$b.gpu.csv 2>/tmp/gpucheck/$b.err
  echo "$b: exit $? $(tail -n 1 /tmp/gpucheck/$b.err)"
done
tar -czf "${OUT:-/tmp}/gpu-check.tar.gz" -C /tmp gpucheck
