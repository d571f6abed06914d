#!/usr/bin/env bash
# Every C++ source of crux is as clang-format (Debian's clang-format 14, .clang-format at
# the root) writes it: the one formatter, checked by the test command.
set -euo pipefail
cd "$1"
mapfile -t sources < <(find src tests python bench fuzz -name '*.cpp' -o -name '*.hpp' | sort)
clang-format-14 --dry-run --Werror "${sources[@]}"
echo "${#sources[@]} sources formatted"
