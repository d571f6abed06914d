#!/usr/bin/env bash
# End-to-end figures of the report (docs/PERFORMANCE.md, "Figures and the report"): the time
# and size of `crux report` on the default `crux paper` folder, the time of `crux figures`,
# and the frame rate of a long replay in headless chromium.
#   bash bench/report_timing.sh [CRUX] [WORK_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
crux="${1:-build/release/crux}"
work="${2:-/tmp/crux-report-bench}"
mkdir -p "$work"

median() { sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
seconds() { /usr/bin/time -f "%e" "$@" 2>&1 >/dev/null | tail -1; }

[ -f "$work/paper/summary.json" ] || "$crux" paper -o "$work/paper" --overwrite > /dev/null
report_s=$(for _ in 1 2 3 4 5; do seconds "$crux" report "$work/paper" -o "$work/paper.html"; done | median)
figures_s=$(for _ in 1 2 3 4 5; do seconds "$crux" figures "$work/paper"; done | median)
bytes=$(stat -c %s "$work/paper.html")
echo "crux report of the default crux paper folder: ${report_s} s (median of 5), ${bytes} bytes"
echo "crux figures of the same folder: ${figures_s} s (median of 5)"

# A long climb: this run's last completed episode is its first long one (763 moves).
"$crux" train --wall-seed 3 --seed 5 --iterations 2000 -o "$work/long" --overwrite > /dev/null
"$crux" report "$work/long" --climb last -o "$work/long.html" --json | grep -E '"(bytes|replay_moves|replay_frames|seconds)"'
node tests/browser/replay_check.mjs --report "$work/long.html" --out "$work/long-screens" --fps
