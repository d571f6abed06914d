#!/usr/bin/env bash
# The static model's cost against the kinematic one (docs/PERFORMANCE.md, "Static
# equilibrium"; issue 26's target: at most 2 times): `crux paper` under each physics model,
# one after the other, repeated; medians of the wall-clock and CPU (user + system) seconds,
# and their ratios. Further arguments go to both `crux paper` runs (e.g. --walls 10
# --seeds-per-wall 1). Run it on an idle machine.
#   bash bench/static_cost.sh [CRUX] [WORK_DIR] [REPETITIONS] [crux paper flags...]
set -euo pipefail
cd "$(dirname "$0")/.."
crux="${1:-build/release/crux}"
work="${2:-/tmp/crux-static-cost}"
repetitions="${3:-3}"
shift $(($# < 3 ? $# : 3))
mkdir -p "$work"

median() { sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
: > "$work/times"
for _ in $(seq "$repetitions"); do
  for model in kinematic static; do
    /usr/bin/time -a -o "$work/times" -f "$model %e %U %S" \
      "$crux" paper --physics-model "$model" -o "$work/$model" --overwrite "$@" > /dev/null
  done
done
for model in kinematic static; do
  wall=$(awk -v m="$model" '$1 == m { print $2 }' "$work/times" | median)
  cpu=$(awk -v m="$model" '$1 == m { print $3 + $4 }' "$work/times" | median)
  echo "$model: ${wall} s wall-clock, ${cpu} s CPU (medians of $repetitions)"
  eval "${model}_wall=$wall ${model}_cpu=$cpu"
done
# shellcheck disable=SC2154  # set by the eval above
awk -v sw="$static_wall" -v kw="$kinematic_wall" -v sc="$static_cpu" -v kc="$kinematic_cpu" \
  'BEGIN { printf "static / kinematic: %.2f wall-clock, %.2f CPU\n", sw / kw, sc / kc }'
