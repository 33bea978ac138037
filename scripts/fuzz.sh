#!/usr/bin/env bash
# Builds the fuzz targets (fuzz/) with clang, libFuzzer, AddressSanitizer and
# UndefinedBehaviorSanitizer in their own build folder and runs each for
# SECONDS (default 60), starting from its seed corpus fuzz/corpus/NAME. New
# interesting inputs go to BUILD/corpus/NAME (not into the repository). A
# crash, sanitizer report, hang (an input taking over 10 s) or failed check is
# written to BUILD/findings/NAME/ and fails the run: keep it as a regression
# case in fuzz/regressions/NAME/ once it is fixed (ctest replays those).
#   scripts/fuzz.sh [SECONDS] [NAME...]
#   AMLS_FUZZ_BUILD_DIR  build folder (default: ./build-fuzz)
#   AMLS_JOBS            parallel compile jobs (default: 2)
set -euo pipefail
repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${AMLS_FUZZ_BUILD_DIR:-$repo_root/build-fuzz}"
seconds="${1:-60}"
shift || true
targets=("$@")
if ((${#targets[@]} == 0)); then targets=(ply xyz csv obj off scene surface); fi

# libFuzzer's runtime is not a dependency of clang-14 (docs: TOOLCHAIN "Sanitizers and fuzzing").
"$repo_root/scripts/install_packages.sh" clang libclang-rt-14-dev

launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
# Warnings are g++'s business (the main build); clang's own set would fail this one.
cmake -S "$repo_root" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang \
  -DCMAKE_CXX_COMPILER=clang++ -DAMLS_FUZZ=ON -DAMLS_WERROR=OFF "${launcher[@]}" >/dev/null
cmake --build "$build_dir" --parallel "${AMLS_JOBS:-2}" --target "${targets[@]/#/amls_fuzz_}"

export ASAN_OPTIONS="abort_on_error=1:detect_leaks=1:${ASAN_OPTIONS:-}"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:${UBSAN_OPTIONS:-}"
failed=()
for name in "${targets[@]}"; do
  mkdir -p "$build_dir/corpus/$name" "$build_dir/findings/$name"
  echo "fuzz: $name for ${seconds} s"
  # -timeout: an input running longer is a hang; -rss_limit_mb: one using more memory is a finding too.
  if ! "$build_dir/fuzz/amls_fuzz_$name" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=4096 \
    -print_final_stats=1 -artifact_prefix="$build_dir/findings/$name/" \
    "$build_dir/corpus/$name" "$repo_root/fuzz/corpus/$name" 2>"$build_dir/findings/$name.log"; then
    failed+=("$name")
    tail -n 40 "$build_dir/findings/$name.log"
  fi
  grep -E "^stat::number_of_executed_units|^Done" "$build_dir/findings/$name.log" | tr '\n' ' ' || true
  echo
done
if ((${#failed[@]})); then
  echo "fuzz: findings in ${failed[*]} (inputs in $build_dir/findings/)" >&2
  exit 1
fi
echo "fuzz: no findings in ${targets[*]}"
