#!/bin/bash
# Thread scaling and GPU frames on a many-core machine, with binaries built elsewhere.
#
# Build without OSMesa (it cannot travel: it pulls in LLVM) and gather what the binaries need:
#   cmake -S . -B build-device -G Ninja -DCMAKE_BUILD_TYPE=Release -DAMLS_WITH_OSMESA=OFF -DAMLS_WITH_EGL=ON
#   ninja -C build-device amls amls_render_bench
#   tools/scaling/run.sh --gather build-device DIR      # copies the binaries, libEGL, libGLdispatch, libstb, scenes
# then on the machine (NVIDIA's EGL vendor file is found at /usr/local/nvidia or named by
# __EGL_VENDOR_LIBRARY_FILENAMES):
#   DIR/run.sh OUT_DIR
# It writes amls bench JSON per thread count (1, 2, 4, 8, 16), the 1M local drag at 2 and 16
# threads, amls_render_bench's table (100k, 1M, 4M splats), byte identity of outputs across
# thread counts, and amls deform's report for the 1M drag scene.
set -u
here="$(cd "$(dirname "$0")" && pwd)"
if [ "${1:-}" = --gather ]; then
  build="$2" dir="$3"
  mkdir -p "$dir/lib"
  cp "$build/app/amls" "$build/bench/amls_render_bench" "$here/run.sh" "$dir/"
  for lib in libEGL.so.1 libGLdispatch.so.0 libstb.so.0; do cp -L "/lib/x86_64-linux-gnu/$lib" "$dir/lib/"; done
  scenes="$(cd "$here/../.." && pwd)/assets/scenes/drag_sphere.json"
  # The drag_sphere scene at a million points: h scaled with the points, the pulled handle by 20 h.
  jq '.shape.points=1000000 | .grid.spacing=0.00097 | .stages[0].targets[0].handles[3][2]=0.8194' "$scenes" \
    > "$dir/drag_1m.json"
  exit 0
fi
out="${1:?usage: run.sh OUT_DIR (or --gather BUILD DIR)}"
mkdir -p "$out" && cd "$out" || exit 1
export LD_LIBRARY_PATH="$here/lib:/usr/local/nvidia/lib64:${LD_LIBRARY_PATH:-}"
vendor=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
[ -f "$vendor" ] && export __EGL_VENDOR_LIBRARY_FILENAMES="${__EGL_VENDOR_LIBRARY_FILENAMES:-$vendor}"
log() { echo "=== $* ($(date +%T))"; }
log render
timeout 100 "$here/amls_render_bench" 20 100000 1000000 4000000 2>&1 | tee render.txt
log bench
for t in 1 2 4 8 16; do
  timeout 150 "$here/amls" bench --threads $t --only 1000k --only Enright --json bench_t$t.json 2>&1 | tail -2
done
for t in 2 16; do
  timeout 90 "$here/amls" bench --threads $t --only "drag 1M local" --json drag_t$t.json 2>&1 | tail -1
done
log identity
for t in 1 2 16; do
  timeout 60 "$here/amls" vortex --grid 128 --threads $t --out v$t.xyz > /dev/null 2>&1
  timeout 60 "$here/amls" enright --grid 64 --threads $t --out e$t.ply > /dev/null 2>&1
  timeout 90 "$here/amls" deform "$here/drag_1m.json" --resample local --threads $t --tracers 1 --max-steps 3 \
    --out-dir d$t > /dev/null 2>&1
done
md5sum v*.xyz e*.ply d*/frame_00003.ply 2>&1 | tee identity.txt
log deform
timeout 120 "$here/amls" deform "$here/drag_1m.json" --resample local --threads 16 --tracers 1 --json deform_1m.json \
  2>&1 | grep -E "time:|points:"
log end
