#!/usr/bin/env bash
# README's second command: install, build and run every test, in the release build and
# under AddressSanitizer + UndefinedBehaviorSanitizer, then fuzz the readers for a
# bounded time (the fuzz preset: clang, libFuzzer, the same sanitizers).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
for preset in release asan fuzz; do
  cmake --preset "$preset"
  cmake --build --preset "$preset"
  ctest --preset "$preset"
done
