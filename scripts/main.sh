#!/usr/bin/env bash
# README's first command: install, build (release) and run the main job. It builds only the
# crux binary, which the job needs, not the tests, the benchmark or the Python module.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake --preset release
cmake --build --preset release --target crux
./build/release/crux paper --overwrite
./build/release/crux report out/paper -o out/paper-report.html
