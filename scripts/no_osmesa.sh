#!/usr/bin/env bash
# Builds amls without OSMesa (-DAMLS_WITH_OSMESA=OFF: headless OpenGL through EGL alone, as
# on Mesa 25.1 and later, which removed OSMesa) in its own build folder, and runs the tests
# there. Only the headless rendering code differs from an OSMesa build, so by default only
# what links it is built and run: the tests labelled `render` (amls_render_tests: the
# renderer, the backend picker, `amls render`'s path; and `amls render` end to end), plus
# the two render benchmarks built to show that they link. AMLS_NO_OSMESA_ALL=1 builds
# everything and runs the whole suite instead. Extra arguments go to ctest.
#   AMLS_NO_OSMESA_BUILD_DIR  build folder (default: ./build-no-osmesa)
#   AMLS_NO_OSMESA_ALL        1: every target and every test (default: 0)
#   AMLS_JOBS                 parallel compile jobs and tests (default: 2)
set -euo pipefail
repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${AMLS_NO_OSMESA_BUILD_DIR:-$repo_root/build-no-osmesa}"
jobs="${AMLS_JOBS:-2}"

"$repo_root/scripts/install_packages.sh" libegl-dev

launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
# AMLS_WITH_EGL=ON: without EGL there would be no headless OpenGL at all, so say so at once.
cmake -S "$repo_root" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DAMLS_WITH_OSMESA=OFF \
  -DAMLS_WITH_EGL=ON "${launcher[@]}" >/dev/null
if [[ "${AMLS_NO_OSMESA_ALL:-0}" == 1 ]]; then
  cmake --build "$build_dir" --parallel "$jobs"
  ctest --test-dir "$build_dir" --output-on-failure --parallel "$jobs" "$@"
else
  cmake --build "$build_dir" --parallel "$jobs" --target amls amls_render_tests amls_render_bench amls_upload_bench
  ctest --test-dir "$build_dir" --output-on-failure --parallel "$jobs" -L '^render$' "$@"
fi
# Nothing in this build may have linked OSMesa.
if ldd "$build_dir/app/amls" "$build_dir/tests/amls_render_tests" | grep libOSMesa; then
  echo "no_osmesa: a program built with AMLS_WITH_OSMESA=OFF links OSMesa" >&2
  exit 1
fi
