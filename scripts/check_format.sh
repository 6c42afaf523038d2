#!/usr/bin/env bash
# Checks that the tracked C++ sources follow .clang-format (100 columns, Google base style).
# Prints clang-format's diagnostics and exits non-zero on the first file that differs; changes
# nothing. Usage: scripts/check_format.sh [FILE...]  (default: every tracked .cpp / .hpp)
set -euo pipefail
cd "$(dirname "$0")/.."
if ! command -v clang-format >/dev/null; then
  echo "check_format: clang-format is not installed (apt-get install clang-format)" >&2
  exit 2
fi
if [ "$#" -gt 0 ]; then
  files=("$@")
else
  mapfile -t files < <(git ls-files '*.cpp' '*.hpp' '*.h' '*.cc')
fi
[ "${#files[@]}" -gt 0 ] || exit 0
clang-format --dry-run -Werror "${files[@]}"
