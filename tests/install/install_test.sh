#!/usr/bin/env bash
# cmake --install into a temporary prefix, then use the install from an unrelated folder:
# crux finds its model beside itself, the Python module (when built) imports from the
# prefix and finds the same model, and a consumer project builds against
# find_package(crux) and computes forward kinematics.
#   install_test.sh BUILD_DIR CONSUMER_SOURCE CXX_COMPILER CXX_FLAGS LINKER_FLAGS
set -euo pipefail
build=$1 consumer=$2 cxx_compiler=$3 cxx_flags=$4 linker_flags=$5
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
mkdir "$work/elsewhere" && cd "$work/elsewhere"
unset CRUX_MODEL_DIR

"$work/prefix/bin/crux" model --json > model.json
grep -q '"dof_revolute": 32' model.json || { echo "crux model --json from the install:"; cat model.json; exit 1; }
"$work/prefix/bin/crux" train --wall-seed 3 --iterations 200 -o run > /dev/null
for file in iterations.csv episodes.csv q_grid.bin climb.csv config.toml summary.json; do
  [ -s "run/$file" ] || { echo "crux train from the install wrote no run/$file"; exit 1; }
done

python_package=$(find "$work/prefix/lib" -path '*/dist-packages/crux/__init__.py' 2> /dev/null | head -n 1)
if [ -n "$python_package" ]; then
  PYTHONPATH=$(dirname "$(dirname "$python_package")") /usr/bin/python3 -c '
import sys, crux
model = crux.BodyModel.load()
assert model.source.startswith(sys.argv[1]), model.source
assert crux.__file__.startswith(sys.argv[1]), crux.__file__
print("python from the install:", model)' "$work/prefix"
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
