#!/usr/bin/env bash
# Builds tools/resample_drift/resample_drift.cpp against the core library's layers in build/core
# (run the project's build first) into build/resample_drift and runs it.
#   tools/resample_drift/build_and_run.sh torus 128 4 10
#   tools/resample_drift/build_and_run.sh enright 128 5
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
"${CXX:-g++}" -O2 -std=c++20 -I"$root" -isystem /usr/include/eigen3 "$root/tools/resample_drift/resample_drift.cpp" \
  "$root"/build/core/{run,io,deform,resample,surface,geometry,util}/libamls_core_*.a -lpthread -o "$root/build/resample_drift"
exec "$root/build/resample_drift" "$@"
