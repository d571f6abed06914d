#!/usr/bin/env bash
# README's first command: install, build (release) and run the main job. It builds only the
# crux binary, which the job needs, not the tests, the benchmark or the Python module.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake --preset release
cmake --build --preset release --target crux
./build/release/crux paper --overwrite
# The exact plan of the first training wall under the static model, performed in MuJoCo;
# the report shows it after the paper's kinematic replay.
./build/release/crux perform --wall-file out/paper/walls/training_0.json --overwrite -o out/paper-performed
./build/release/crux report out/paper --performed out/paper-performed -o out/paper-report.html
