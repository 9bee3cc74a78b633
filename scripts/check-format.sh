#!/bin/bash
# Checks that every C++ source and header follows the repository's .clang-format (clang-format
# 14, as Debian 12 ships it). Prints the offending files and exits 1 if any is not formatted.
set -euo pipefail
cd "$(dirname "$0")/.."
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files '*.cpp' '*.hpp')
else  # a tree without git (an exported copy): every source outside build folders
  mapfile -t files < <(find . -path './build*' -prune -o \( -name '*.cpp' -o -name '*.hpp' \) -print)
fi
if ! clang-format --dry-run --Werror "${files[@]}" 2>/tmp/rheomag-format.log; then
  grep -o '^[^:]*' /tmp/rheomag-format.log | sort -u | sed 's/^/not formatted: /' >&2
  echo "run: clang-format -i \$(git ls-files '*.cpp' '*.hpp')" >&2
  exit 1
fi
echo "format: ${#files[@]} files follow .clang-format"
