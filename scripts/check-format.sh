#!/usr/bin/env bash
# Fails, listing the files, when the project's own C++ is not clang-formatted
# (.clang-format). Generated code lives in build/ and is not checked.
# Fix with: clang-format -i $(git ls-files '*.cpp' '*.h')
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -t files < <(git ls-files '*.cpp' '*.h' '*.cc' '*.hpp')
off=()
for f in "${files[@]}"; do
  [ -f "$f" ] || continue
  clang-format --dry-run -Werror "$f" >/dev/null 2>&1 || off+=("$f")
done
if [ ${#off[@]} -ne 0 ]; then
  echo "format: ${#off[@]} file(s) are not clang-formatted:"
  printf '  %s\n' "${off[@]}"
  echo "fix with: clang-format -i ${off[*]}"
  exit 1
fi
echo "format: ${#files[@]} files clang-formatted"
