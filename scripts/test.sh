#!/usr/bin/env bash
# Set-up (packages, configure, build), then the whole test suite through ctest.
set -euo pipefail
repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$repo_root/scripts/setup.sh" "$@"
ctest --test-dir "${AMLS_BUILD_DIR:-$repo_root/build}" --output-on-failure --parallel "$(nproc)"
