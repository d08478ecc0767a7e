#!/usr/bin/env bash
# Every C source and header keeps the committed .clang-format style:
#   format_check.sh REPO_ROOT
# Exit 0 when clang-format finds nothing to change, 1 (naming the files)
# when it does, 77 (skipped) when clang-format is missing or is not major
# version 14, the one the tree is formatted with: other versions format some
# constructs differently, so their verdict says nothing about the tree.
set -euo pipefail
root="$1"
command -v clang-format >/dev/null || { echo "format_check: clang-format not found: skipped"; exit 77; }
version=$(clang-format --version)
major=$(sed -E 's/.*version ([0-9]+)\..*/\1/' <<<"$version")
if [ "$major" != "14" ]; then
  echo "format_check: $version is not major version 14: skipped"
  exit 77
fi
cd "$root"
bad=()
while IFS= read -r -d '' f; do
  if ! clang-format --dry-run --Werror "$f" >/dev/null 2>&1; then bad+=("$f"); fi
done < <(find src include test bench -name '*.[ch]' -print0 | sort -z)
n=$(find src include test bench -name '*.[ch]' | wc -l)
[ "$n" -gt 0 ] || { echo "format_check: no C sources found under $root"; exit 1; }
if [ ${#bad[@]} -gt 0 ]; then
  echo "format_check: ${#bad[@]} of $n files differ from .clang-format (run clang-format -i on them):"
  printf '  %s\n' "${bad[@]}"
  exit 1
fi
echo "format_check: $n files keep .clang-format"
