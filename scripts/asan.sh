#!/usr/bin/env bash
# Builds everything with AddressSanitizer and UndefinedBehaviorSanitizer in its
# own build folder and runs the whole ctest suite there: an invalid memory
# access, a leak or undefined behaviour fails the test it happens in. Extra
# arguments go to ctest (e.g. -R scene).
#   AMLS_ASAN_BUILD_DIR  build folder (default: ./build-asan)
#   AMLS_JOBS            parallel compile jobs and tests (default: 2)
set -euo pipefail
repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${AMLS_ASAN_BUILD_DIR:-$repo_root/build-asan}"
jobs="${AMLS_JOBS:-2}"

launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
# -O1 with assertions (Eigen's bounds checks too): quicker to build than -O2 and
# still quick enough to run the suite. -g1: line tables for the reports' stacks,
# without the full debug information that slows the build.
cmake -S "$repo_root" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DAMLS_SANITIZE_ADDRESS=ON \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1" "${launcher[@]}" >/dev/null
cmake --build "$build_dir" --parallel "$jobs"
# Leaks inside Mesa's software renderer (EGL or OSMesa, llvmpipe) are not ours.
export ASAN_OPTIONS="abort_on_error=1:detect_leaks=1:strict_string_checks=1:${ASAN_OPTIONS:-}"
export LSAN_OPTIONS="suppressions=$repo_root/scripts/sanitizers/lsan_suppressions.txt:print_suppressions=0:${LSAN_OPTIONS:-}"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:${UBSAN_OPTIONS:-}"
ctest --test-dir "$build_dir" --output-on-failure --parallel "$jobs" "$@"
