#!/usr/bin/env bash
# Enright's point set against the exact shape, frame by frame (see frames.cpp
# and sheets.py).
#
#   tools/enright_sheets/run.sh GRID EVERY DIR [STEP...]
#     e.g. tools/enright_sheets/run.sh 64 10 /tmp/frames 70 100 150 200 260 290
#
# Compiles frames.cpp against the static libraries of build/ (configure and
# `ninja -C build amls amls_python` first), writes every EVERY-th frame and the per-step
# figures (DIR/steps.txt), then runs sheets.py on the frames of the STEPs.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="${BUILD_DIR:-$root/build}"
[[ $# -ge 3 ]] || { sed -n 2,11p "$0"; exit 2; }
grid="$1" every="$2" dir="$3"
shift 3

libs=()
for lib in run deform resample surface io geometry util; do libs+=("$build/core/$lib/libamls_core_$lib.a"); done
exe="$build/enright_sheets_frames"
if [[ ! -x "$exe" || "$here/frames.cpp" -nt "$exe" ]]; then
  "${CXX:-g++}" -std=c++20 -O2 -Wall -Wextra -I"$root" -isystem /usr/include/eigen3 "$here/frames.cpp" \
    "${libs[@]}" "${libs[@]}" -lpthread -o "$exe"
fi
mkdir -p "$dir"
"$exe" "$grid" "$every" "$dir" > "$dir/steps.txt"
frames=()
for step in "$@"; do frames+=("$(printf '%s/f%03d.ply' "$dir" "$step")"); done
if [[ ${#frames[@]} -gt 0 ]]; then PYTHONPATH="$build/python${PYTHONPATH:+:$PYTHONPATH}" python3 "$here/sheets.py" "$grid" "${frames[@]}"; fi
