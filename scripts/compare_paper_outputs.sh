#!/usr/bin/env bash
# Compares the `crux paper` output folders of two builds, to show that a change moved
# code but not numbers: every run file, wall and figure CSV byte for byte, summary.json
# apart from the fields that name the build and its timing, and the printed report.
#
#   scripts/compare_paper_outputs.sh OLD_CRUX "OLD FLAGS" NEW_CRUX "NEW FLAGS"
#
# Flags are given per build because flag names may differ between versions.
set -euo pipefail
if [ $# -ne 4 ]; then
  echo "usage: $0 OLD_CRUX \"OLD FLAGS\" NEW_CRUX \"NEW FLAGS\"" >&2
  exit 2
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# shellcheck disable=SC2086  # the flags are meant to split into words
"$1" paper $2 -o "$work/old" > "$work/old.txt" 2> /dev/null
# shellcheck disable=SC2086
"$3" paper $4 -o "$work/new" > "$work/new.txt" 2> /dev/null
status=0
if diff -rq "$work/old" "$work/new" --exclude=summary.json --exclude=config.toml --exclude=q_grid.bin; then
  echo "identical: $(find "$work/old" -type f ! -name summary.json ! -name config.toml ! -name q_grid.bin | wc -l) run files, walls and figure CSVs"
else
  status=1
fi
# Q-table files by content: version 2 added the state space to the header, so a
# version 1 and a version 2 file of the same table differ in header and checksum only.
/usr/bin/python3 - "$work/old" "$work/new" <<'PY' || status=1
import pathlib, struct, sys
def table(path):
    data = path.read_bytes()
    version, actions = struct.unpack("<II", data[8:16])
    rows_at = 16 if version == 1 else 20 + struct.unpack("<I", data[16:20])[0]
    return actions, data[rows_at:-8]
old_root, new_root = (pathlib.Path(p) for p in sys.argv[1:3])
files = sorted(old_root.rglob("q_grid.bin"))
differing = [str(f.relative_to(old_root)) for f in files if table(f) != table(new_root / f.relative_to(old_root))]
if differing:
    print("q_grid.bin tables differ:", ", ".join(differing))
    sys.exit(1)
print(f"identical: the tables of {len(files)} q_grid.bin files")
PY
# Fields that name the build or time it; wall_pairs was added beside walls (summary version 3).
/usr/bin/python3 - "$work/old/summary.json" "$work/new/summary.json" <<'PY' || status=1
import json, sys
old, new = (json.load(open(path)) for path in sys.argv[1:3])
for summary in (old, new):
    for key in ("format", "version", "kind", "provenance", "seconds", "wall_pairs"):
        summary.pop(key, None)
# Keys added to a wall's entry later (plan_stopped_at_limit) are new facts, not changed numbers.
for old_wall, new_wall in zip(old.get("walls", []), new.get("walls", [])):
    for key in set(new_wall) - set(old_wall):
        new_wall.pop(key)
differing = sorted(key for key in set(old) | set(new) if old.get(key) != new.get(key))
if differing:
    print("summary.json differs in:", ", ".join(differing))
    sys.exit(1)
print("identical: summary.json apart from format, version, kind, provenance, seconds, wall_pairs and added wall keys")
PY
if diff <(grep -v '^wrote ' "$work/old.txt") <(grep -v '^wrote ' "$work/new.txt") > /dev/null; then
  echo "identical: the printed report"
else
  echo "the printed reports differ"
  status=1
fi
exit $status
