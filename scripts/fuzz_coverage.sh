#!/usr/bin/env bash
# How much of the static model (src/physics/*.cpp, src/climbing/stance_check.cpp) the
# stance_check fuzz harness reaches: a build of its own with clang's source-based
# coverage and no sanitizers runs the harness once on each input of the corpus folders,
# then llvm-cov reports each file's line and region coverage (docs/RELIABILITY.md).
#
#   bash scripts/fuzz_coverage.sh BUILD_DIR [CORPUS_FOLDER...]
#
# The corpus defaults to the seeds and, when a fuzz run left them, the inputs it found
# (build/fuzz/fuzz/found/stance_check). Each input runs in its own process, so that one
# that fails (named at the end) loses only its own counts.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:?usage: scripts/fuzz_coverage.sh BUILD_DIR [CORPUS_FOLDER...]}"
shift
corpus=("$@")
if [ ${#corpus[@]} -eq 0 ]; then
  corpus=("$root/fuzz/corpus/stance_check")
  if [ -d "$root/build/fuzz/fuzz/found/stance_check" ]; then corpus+=("$root/build/fuzz/fuzz/found/stance_check"); fi
fi

# -fsanitize=fuzzer-no-link: the harness links libFuzzer's main, which wants the
# instrumentation it counts on; -O1 as the fuzz preset builds it.
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 \
  -DCMAKE_CXX_FLAGS="-fprofile-instr-generate -fcoverage-mapping -fsanitize=fuzzer-no-link" \
  -DCMAKE_EXE_LINKER_FLAGS=-fprofile-instr-generate -DCRUX_BUILD_FUZZ=ON -DCRUX_BUILD_TESTS=OFF \
  -DCRUX_BUILD_BENCH=OFF -DCRUX_BUILD_PYTHON=OFF -DCRUX_BUILD_END_TO_END_TESTS=OFF
cmake --build "$build" --target stance_check_fuzz

harness="$build/fuzz/stance_check_fuzz"
profiles="$build/coverage"
rm -rf "$profiles"
mkdir -p "$profiles"
inputs=0
failed=()
while IFS= read -r -d '' input; do
  inputs=$((inputs + 1))
  # %4m: the processes merge their counts into a pool of four files as they end.
  LLVM_PROFILE_FILE="$profiles/stance_check-%4m.profraw" "$harness" "$input" >/dev/null 2>&1 || failed+=("$input")
done < <(find "${corpus[@]}" -type f -print0 | sort -z)

llvm-profdata-14 merge -sparse "$profiles"/*.profraw -o "$profiles/stance_check.profdata"
echo "stance_check harness: ${inputs} inputs from ${corpus[*]}"
llvm-cov-14 report "$harness" -instr-profile="$profiles/stance_check.profdata" "$root"/src/physics/*.cpp \
  "$root/src/climbing/stance_check.cpp"
if [ ${#failed[@]} -gt 0 ]; then
  echo "${#failed[@]} inputs failed, their counts left out:"
  printf '  %s\n' "${failed[@]}"
fi
