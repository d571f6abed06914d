#!/usr/bin/env bash
# README's first command: install, build (release) and run the main job.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake --preset release
cmake --build --preset release
./build/release/crux paper --overwrite
./build/release/crux report out/paper -o out/paper-report.html
