#!/usr/bin/env bash
# Formatting is checked, not hoped for: every C++ file of the repository against .clang-format
# (clang-format --dry-run -Werror). Exit 1 naming the files and lines that differ.
# Usage: check_format.sh [--fix]   (--fix: format the files in place instead)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
command -v clang-format >/dev/null || { echo "check_format: clang-format is not installed" >&2; exit 1; }
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files -- '*.h' '*.cpp')
else  # a source tree without git: the project's own folders
  mapfile -t files < <(find app bench fuzz planner render tests -name '*.h' -o -name '*.cpp' | sort)
fi
if [[ "${1:-}" == --fix ]]; then
  clang-format -i "${files[@]}"
  exit 0
fi
clang-format --dry-run -Werror "${files[@]}"
echo "check_format: ${#files[@]} files formatted as .clang-format says ($(clang-format --version))"
