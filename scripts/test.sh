#!/usr/bin/env bash
# README's second command: install, build and run every test. The release build (GCC) runs
# them all; the sanitized build (clang, AddressSanitizer + UndefinedBehaviorSanitizer,
# assertions on) runs all but the slow and browser ones, and the readers' libFuzzer
# harnesses, built in it, for a bounded time each. docs/TESTING.md says which test runs
# where, and how long each stage takes.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
for preset in release asan; do
  cmake --preset "$preset"
  cmake --build --preset "$preset"
  ctest --preset "$preset"
done
