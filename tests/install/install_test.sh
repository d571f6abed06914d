#!/usr/bin/env bash
# cmake --install into a temporary prefix, then use the install from an unrelated folder:
# crux finds its model beside itself and reads the installed walls, the examples are
# installed, the Python module (when built) imports from the prefix, finds the same model
# and runs the installed example, and a consumer project builds against find_package(crux)
# and computes forward kinematics.
#   install_test.sh BUILD_DIR CONSUMER_SOURCE CXX_COMPILER CXX_FLAGS LINKER_FLAGS
set -euo pipefail
build=$1 consumer=$2 cxx_compiler=$3 cxx_flags=$4 linker_flags=$5
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
mkdir "$work/elsewhere" && cd "$work/elsewhere"
unset CRUX_MODEL_DIR

"$work/prefix/bin/crux" model --json > model.json
grep -q '"dof_revolute": 32' model.json || { echo "crux model --json from the install:"; cat model.json; exit 1; }
"$work/prefix/bin/crux" train --wall-seed 3 --iterations 200 -o run > train.out
for file in iterations.csv episodes.csv q_grid.bin climb.csv config.toml summary.json; do
  [ -s "run/$file" ] || { echo "crux train from the install wrote no run/$file"; exit 1; }
done

# README's tour: the repository's walls and examples, under share/crux/ of the prefix.
share="$work/prefix/share/crux"
for wall in "$repo"/walls/*.json; do
  [ -s "$share/walls/$(basename "$wall")" ] || { echo "the install has no share/crux/walls/$(basename "$wall")"; exit 1; }
done
"$work/prefix/bin/crux" wall show --wall-file "$share/walls/board_140.json" > wall.txt
grep -q "140 holds" wall.txt || { echo "crux wall show of the installed board_140.json:"; cat wall.txt; exit 1; }
for example in $(cd "$repo/examples" && find . -type f); do
  cmp -s "$repo/examples/$example" "$share/examples/$example" ||
    { echo "the install's share/crux/examples/$example is not the repository's"; exit 1; }
done

python_package=$(find "$work/prefix/lib" -path '*/dist-packages/crux/__init__.py' 2> "$work/find.err" | head -n 1)
if [ -n "$python_package" ]; then
  python_path=$(dirname "$(dirname "$python_package")")
  PYTHONPATH=$python_path /usr/bin/python3 -c '
import sys, crux
model = crux.BodyModel.load()
assert model.source.startswith(sys.argv[1]), model.source
assert crux.__file__.startswith(sys.argv[1]), crux.__file__
print("python from the install:", model)' "$work/prefix"
  PYTHONPATH=$python_path /usr/bin/python3 "$share/examples/python/q_learning.py" --steps 500 > q_learning.txt
  grep -q "episodes" q_learning.txt || { echo "the installed q_learning.py printed:"; cat q_learning.txt; exit 1; }
elif grep -q "CRUX_BUILD_PYTHON:BOOL=ON" "$build/CMakeCache.txt"; then
  echo "the build has the Python module, but cmake --install put no crux package under $work/prefix/lib"; exit 1
fi

cmake -S "$consumer" -B "$work/consumer" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$work/prefix" \
  -DCMAKE_CXX_COMPILER="$cxx_compiler" \
  -DCMAKE_CXX_FLAGS="$cxx_flags" -DCMAKE_EXE_LINKER_FLAGS="$linker_flags" > "$work/consumer.log"
cmake --build "$work/consumer" >> "$work/consumer.log"
line=$("$work/consumer/consumer" "$work/prefix/share/crux/models/crux_human.urdf")
# docs/MODEL.md: standing, the right palm is at (0, -0.1853, -0.2601) from the root.
case "$line" in
  "right_palm 0.0000 -0.1853 -0.2601") echo "install test: $line" ;;
  *) echo "consumer printed '$line', expected the right palm at (0, -0.1853, -0.2601)"; exit 1 ;;
esac
