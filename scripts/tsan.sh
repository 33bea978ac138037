#!/usr/bin/env bash
# Builds the editor's worker, queue and session tests (amls_editor_core_tests,
# no GL) with -fsanitize=thread in their own build folder and runs them: data
# races and lock-order problems fail the run. Extra arguments go to the test
# executable (e.g. -tc="*cancel*").
#   AMLS_TSAN_BUILD_DIR  build folder (default: ./build-tsan)
#   AMLS_JOBS            parallel compile jobs (default: 2)
set -euo pipefail
repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${AMLS_TSAN_BUILD_DIR:-$repo_root/build-tsan}"

cmake -S "$repo_root" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DAMLS_SANITIZE_THREAD=ON >/dev/null
cmake --build "$build_dir" --parallel "${AMLS_JOBS:-2}" --target amls_editor_core_tests
# halt_on_error: the first report fails the run; second_deadlock_stack: both stacks of a lock-order report.
TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1 ${TSAN_OPTIONS:-}" \
  "$build_dir/tests/amls_editor_core_tests" "$@"
