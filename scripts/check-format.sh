#!/usr/bin/env bash
# Fails (exit 1) when a C++ file of the tree does not obey .clang-format, naming each such file.
# scripts/check-format.sh [--fix]: with --fix, formats them in place instead.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
clang_format="${CLANG_FORMAT:-clang-format}"
command -v "$clang_format" >/dev/null || { echo "check-format: $clang_format not found (scripts/install-deps.sh installs it)" >&2; exit 1; }

folders=(engine app tests bench python)
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then  # tracked and new files, not the build trees
  mapfile -t files < <(git ls-files -co --exclude-standard -- "${folders[@]/%//*.[ch]pp}" | while read -r f; do [[ -f "$f" ]] && echo "$f"; done)
else
  mapfile -t files < <(find "${folders[@]}" -name '*.[ch]pp' 2>/dev/null | sort)
fi
if [[ "${1:-}" == "--fix" ]]; then
  "$clang_format" -i "${files[@]}"
  exit 0
fi
# One clang-format run over every file; it names each offending file in its warnings. Any other
# failure (an unknown key in .clang-format, a file it cannot read) fails the check too.
status=0
report="$("$clang_format" --dry-run --Werror "${files[@]}" 2>&1)" || status=$?
mapfile -t bad < <(sed -n 's/^\([^:]*\):[0-9]*:[0-9]*: error: code should be clang-formatted.*/\1/p' <<<"$report" | sort -u)
if ((${#bad[@]})); then
  echo "check-format: ${#bad[@]} of ${#files[@]} files do not obey .clang-format (scripts/check-format.sh --fix):" >&2
  printf '  %s\n' "${bad[@]}" >&2
  exit 1
fi
if ((status != 0)); then
  echo "check-format: $clang_format failed (status $status):" >&2
  head -n 12 <<<"$report" >&2
  exit 1
fi
echo "check-format: ${#files[@]} files obey .clang-format"
