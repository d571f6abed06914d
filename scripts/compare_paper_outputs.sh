#!/usr/bin/env bash
# Compares the `crux paper` output folders of two builds, to show that a change moved
# code but not numbers: every run file, wall and figure byte for byte (a CSV whose text
# differs, value by value), summary.json apart from the fields that name the build and
# its timing (with how far its numbers moved, if they did), and the printed report.
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
# Files byte for byte; a CSV whose text differs is compared by value, cell by cell, since
# a writer may change how it spells a number (196.59999999999999 and 196.6 are one double).
/usr/bin/python3 - "$work/old" "$work/new" <<'PY' || status=1
import csv, pathlib, sys
old_root, new_root = (pathlib.Path(p) for p in sys.argv[1:3])
skip = {"summary.json", "config.toml", "q_grid.bin"}
old_files = sorted(p.relative_to(old_root) for p in old_root.rglob("*") if p.is_file() and p.name not in skip)
new_files = sorted(p.relative_to(new_root) for p in new_root.rglob("*") if p.is_file() and p.name not in skip)
if old_files != new_files:
    print("the folders hold different files:", sorted(set(map(str, old_files)) ^ set(map(str, new_files))))
    sys.exit(1)
def cell(text):
    try:
        return float(text)
    except ValueError:
        return text
same_bytes, same_values, differing = 0, [], []
for name in old_files:
    a, b = (old_root / name).read_bytes(), (new_root / name).read_bytes()
    if a == b:
        same_bytes += 1
    elif name.suffix == ".csv" and [[cell(c) for c in row] for row in csv.reader(a.decode().splitlines())] == \
            [[cell(c) for c in row] for row in csv.reader(b.decode().splitlines())]:
        same_values.append(str(name))
    else:
        differing.append(str(name))
print(f"identical: {same_bytes} run files, walls and figures byte for byte")
if same_values:
    print(f"the same values, spelt differently: {len(same_values)} CSV files ({', '.join(same_values[:3])}, ...)")
if differing:
    print("differ:", ", ".join(differing))
    sys.exit(1)
PY
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
def numbers_apart(a, b, path, out):
    """Leaves where the two differ: (path, relative difference) for numbers, None otherwise."""
    if isinstance(a, dict) and isinstance(b, dict) and a.keys() == b.keys():
        for key in a:
            numbers_apart(a[key], b[key], f"{path}.{key}", out)
    elif isinstance(a, list) and isinstance(b, list) and len(a) == len(b):
        for i, (x, y) in enumerate(zip(a, b)):
            numbers_apart(x, y, f"{path}[{i}]", out)
    elif isinstance(a, (int, float)) and isinstance(b, (int, float)) and not isinstance(a, bool):
        if a != b:
            out.append((path, abs(a - b) / max(abs(a), abs(b))))
    elif a != b:
        out.append((path, None))
differing = sorted(key for key in set(old) | set(new) if old.get(key) != new.get(key))
if differing:
    apart = []
    for key in differing:
        numbers_apart(old.get(key), new.get(key), key, apart)
    if any(r is None for _, r in apart):
        print("summary.json differs in:", ", ".join(p for p, r in apart if r is None))
        sys.exit(1)
    print(f"summary.json: {len(apart)} numbers in {', '.join(differing)} moved, by at most "
          f"{max(r for _, r in apart):.1e} of their value")
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
