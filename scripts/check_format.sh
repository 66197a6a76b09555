#!/usr/bin/env bash
# Checks that every tracked C++ file is formatted by .clang-format, with clang-format 14 (Debian
# 12's; other versions format some constructs differently). Exit 0: formatted; 1: a file
# differs (listed; `scripts/check_format.sh --fix` formats them); 77: no clang-format-14 here.
#   scripts/check_format.sh [--fix]
set -euo pipefail
cd "$(dirname "$0")/.."
tool=$(command -v clang-format-14 || true)
if [[ -z "$tool" ]]; then
  echo "check_format: clang-format-14 not found (apt-get install clang-format-14); skipped"
  exit 77
fi
mapfile -t files < <(git ls-files '*.cc' '*.h')
if [[ "${1:-}" == "--fix" ]]; then
  "$tool" -i "${files[@]}"
  echo "check_format: formatted ${#files[@]} files"
  exit 0
fi
bad=$("$tool" --dry-run "${files[@]}" 2>&1 | grep -E -o '^[^:]+:[0-9]+:[0-9]+: warning' | cut -d: -f1 | sort -u || true)
if [[ -n "$bad" ]]; then
  echo "check_format: not formatted by .clang-format (fix: scripts/check_format.sh --fix):"
  echo "$bad" | sed 's/^/  /'
  exit 1
fi
echo "check_format: ${#files[@]} files formatted"
