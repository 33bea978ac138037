#!/usr/bin/env bash
# Set-up (packages, configure, build), then the main job: the single-vortex
# test at a small grid, printing its report.
set -euo pipefail
repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# Only the command line: the editor, tests and benchmarks are not needed for it.
AMLS_BUILD_TARGETS=amls "$repo_root/scripts/setup.sh"
"${AMLS_BUILD_DIR:-$repo_root/build}/app/amls" vortex --grid 128
