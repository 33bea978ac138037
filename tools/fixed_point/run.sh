#!/usr/bin/env bash
# Whether resampling a resample at the same h is a fixed point, on any point sets:
#   tools/fixed_point/run.sh [--amls PATH] [--keep DIR] FILE... [-- AMLS_RESAMPLE_OPTIONS...]
# For each FILE: r1 = `amls resample FILE` (defaults, plus the options after --), then r2, r3, r4 =
# `amls resample` of the previous output with --spacing H (r1's h, read from its `amls spacing`
# comment) and --accept-loss. Prints one line per file: the four point counts, the change of each
# resample after the first (percent), and the share of r3 farther than 0.75 h from r1 (percent),
# with r1's time. The outputs go to a temporary folder (kept with --keep DIR).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
amls="$root/build/app/amls"
keep=""
files=()
while [ $# -gt 0 ]; do
  case "$1" in
    --amls) amls="$2"; shift 2 ;;
    --keep) keep="$2"; shift 2 ;;
    --) shift; break ;;
    *) files+=("$1"); shift ;;
  esac
done
extra=("$@")
[ ${#files[@]} -gt 0 ] || { sed -n 2,8p "${BASH_SOURCE[0]}"; exit 2; }
work="${keep:-$(mktemp -d)}"
mkdir -p "$work"
[ -n "$keep" ] || trap 'rm -rf "$work"' EXIT

count() { grep -a -m1 '^element vertex' "$1" | awk '{print $3}'; }
change() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%+.2f", 100 * (b - a) / a }'; }

printf '%-28s %9s %9s %9s %9s %8s %8s %8s %8s %7s\n' file r1 r2 r3 r4 'r2/r1%' 'r3/r2%' 'r4/r3%' 'far3%' 't1(s)'
for file in "${files[@]}"; do
  name="$(basename "$file")"
  out="$work/${name%.*}"
  start=$(date +%s.%N)
  "$amls" resample "$file" --out "$out.r1.ply" "${extra[@]}" >"$out.log" 2>&1 || { echo "$name: resample failed"; cat "$out.log"; continue; }
  t1=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "%.1f", e - s }')
  h=$(grep -a -m1 '^comment amls spacing' "$out.r1.ply" | awk '{print $4}')
  for k in 2 3 4; do
    "$amls" resample "$out.r$((k - 1)).ply" --spacing "$h" --accept-loss --out "$out.r$k.ply" "${extra[@]}" >>"$out.log" 2>&1 \
      || { echo "$name: resample $k failed"; tail -3 "$out.log"; continue 2; }
  done
  c1=$(count "$out.r1.ply") c2=$(count "$out.r2.ply") c3=$(count "$out.r3.ply") c4=$(count "$out.r4.ply")
  far=$(python3 "$root/tools/fixed_point/far_share.py" "$out.r1.ply" "$out.r3.ply" "$h")
  printf '%-28s %9s %9s %9s %9s %8s %8s %8s %8s %7s\n' "$name" "$c1" "$c2" "$c3" "$c4" \
    "$(change "$c1" "$c2")" "$(change "$c2" "$c3")" "$(change "$c3" "$c4")" "$far" "$t1"
done
