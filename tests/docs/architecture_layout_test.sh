#!/usr/bin/env bash
# docs/architecture.md's "Layout" block and the tree agree: every folder it names exists, every
# tracked folder down to the second level (the third under harness/host/, harness/sdk/ and
# plugins/, where the concepts live; the first under results/, suites/, docs/, scripts/, cmake/, .ci/) is named in
# it, itself or through a folder inside it, and every line says the job of its folders.
#   tests/docs/architecture_layout_test.sh [SOURCE_DIR]
set -euo pipefail
cd "${1:-$(dirname "$0")/../..}"
block=$(awk '/^## Layout/{on=1} on && /^```$/{n++; if (n==2) exit; next} on && n==1' docs/architecture.md)
[[ -n "$block" ]] || { echo "FAIL: no Layout block in docs/architecture.md"; exit 1; }
# The folders a line names: its leading words that end in '/'.
named=$(awk '{for (i = 1; i <= NF && $i ~ /\/$/; i++) print $i}' <<< "$block" | sort -u)
status=0
while IFS= read -r line; do
  job=$(awk '{for (i = 1; i <= NF && $i ~ /\/$/; i++) $i = ""; print}' <<< "$line" | tr -d ' ')
  [[ -n "$job" ]] || { echo "FAIL: this Layout line names no job: $line"; status=1; }
done <<< "$block"
for d in $named; do
  [[ -d "$d" ]] || { echo "FAIL: docs/architecture.md names $d, which does not exist"; status=1; }
done
tracked=$(git ls-files | awk -F/ '
  NF == 1 { next }
  $1 == "results" || $1 == "suites" || $1 == "docs" || $1 == "scripts" || $1 == "cmake" || $1 == ".ci" || NF == 2 { print $1 "/"; next }
  (($1 == "harness" && ($2 == "host" || $2 == "sdk")) || $1 == "plugins") && NF > 3 { print $1 "/" $2 "/" $3 "/"; next }
  { print $1 "/" $2 "/" }' | sort -u)
for d in $tracked; do
  # Named itself, or through a folder inside it (harness/sdk/ by harness/sdk/include/).
  if ! grep -q -F -- "$d" <<< "$(grep "^$d" <<< "$named" || true)"; then
    echo "FAIL: the tracked folder $d is not in docs/architecture.md's Layout block"
    status=1
  fi
done
[[ $status -ne 0 ]] || echo "architecture layout: $(wc -l <<< "$named") folders named, all present; every tracked folder named"
exit $status
