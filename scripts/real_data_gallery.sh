#!/usr/bin/env bash
# scripts/real_data_gallery.sh BUILD_DIR: the figures and pictures of docs/real-data.md.
# Resamples each real file of the realdata tests with no spacing option (after
# `ctest --test-dir BUILD_DIR -L realdata` has fetched them), one at a time,
# prints a Markdown table row per file from the JSON reports, and renders
# pictures into docs/images/real/.
set -euo pipefail
build=$(cd "$1" && pwd)
amls=$build/app/amls
data=$build/cgal_data
work=$build/tests/realdata/gallery
images=$(cd "$(dirname "$0")/.." && pwd)/docs/images/real
mkdir -p "$work" "$images"
files=(data/points_3/kitten.xyz data/points_3/hippo1.ply data/points_3/oni.ply data/points_3/sphere_20k.xyz
       data/points_3/building.ply data/points_3/radar.xyz data/meshes/bunny00.off data/meshes/armadillo.off
       data/meshes/elephant.off data/meshes/fandisk.off)
echo "| file | in the file | h | points out | out / in | input covered | output on the input | time | peak memory |"
echo "|---|---|---|---|---|---|---|---|---|"
for f in "${files[@]}"; do
  name=$(basename "${f%.*}")
  "$amls" resample "$data/$f" --out "$work/$name.ply" --json "$work/$name.json" --threads 2 > "$work/$name.log" 2>&1
  python3 - "$work/$name.json" "$(basename "$f")" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
c = r["coverage"]
print(f"| {sys.argv[2]} | {r['file_points']:,} | {r['h']:.4g} | {r['points_out']:,} | {r['points_out'] / r['file_points']:.2f} | "
      f"{100 * c['input_covered']:.2f} % | {100 * c['output_on_input']:.2f} % | {r['seconds']:.1f} s | {r['peak_memory_mib']:.0f} MiB |")
PY
done
render() { "$amls" render "$1" --out "$images/$2.png" --size 480x360 "${@:3}" > /dev/null; }
for name in kitten radar bunny00 building; do render "$work/$name.ply" "$name"; done
render "$data/data/points_3/kitten.xyz" kitten_input
render "$data/data/points_3/radar.xyz" radar_input
# What the rule replaced: h = 1/256 on the kitten (the old default), and the median
# nearest-neighbour distance on the radar scan (the editor's old rule).
"$amls" resample "$data/data/points_3/kitten.xyz" --out "$work/kitten_h256.ply" --spacing 0.00390625 --accept-loss \
  --json "$work/kitten_h256.json" > "$work/kitten_h256.log" 2>&1
render "$work/kitten_h256.ply" kitten_h256 --spacing 0.00390625
nearest=$(grep -o "median nearest-neighbour distance [0-9.e-]*" "$work/radar.log" | awk '{print $4}')
"$amls" resample "$data/data/points_3/radar.xyz" --out "$work/radar_nearest.ply" --spacing "$nearest" --accept-loss \
  --json "$work/radar_nearest.json" > "$work/radar_nearest.log" 2>&1
render "$work/radar_nearest.ply" radar_nearest
for name in kitten_h256 radar_nearest; do
  python3 -c "import json,sys; r=json.load(open(sys.argv[1])); c=r['coverage']; print(sys.argv[2], 'h', r['h'], 'out', r['points_out'], 'covered', c['input_covered'], 'on input', c['output_on_input'])" "$work/$name.json" "$name"
done
