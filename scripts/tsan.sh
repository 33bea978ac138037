#!/usr/bin/env bash
# Builds the threaded tests with -fsanitize=thread in their own build folder and
# runs them: the thread pool's (amls_thread_tests) and the editor's worker,
# queue and session (amls_editor_core_tests, no GL). Data races and lock-order
# problems fail the run. Extra arguments go to both test executables (e.g.
# -tc="*cancel*").
#   AMLS_TSAN_BUILD_DIR  build folder (default: ./build-tsan)
#   AMLS_JOBS            parallel compile jobs (default: 2)
set -euo pipefail
repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${AMLS_TSAN_BUILD_DIR:-$repo_root/build-tsan}"

launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
cmake -S "$repo_root" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DAMLS_SANITIZE_THREAD=ON \
  "${launcher[@]}" >/dev/null
cmake --build "$build_dir" --parallel "${AMLS_JOBS:-2}" --target amls_thread_tests amls_editor_core_tests
# halt_on_error: the first report fails the run; second_deadlock_stack: both stacks of a lock-order report.
export TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1 ${TSAN_OPTIONS:-}"
"$build_dir/tests/amls_thread_tests" "$@"
"$build_dir/tests/amls_editor_core_tests" "$@"
