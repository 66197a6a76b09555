#!/usr/bin/env bash
# Reruns a suite from scratch and compares every episode with its committed reference output
# (results/<name>/episodes.csv), the decision-time column aside: the check that a build on this
# machine reproduces the committed tables exactly.
#
#   scripts/check_reference.sh suites/baselines.yaml [--jobs N] [--bin PATH]
set -euo pipefail
usage="usage: scripts/check_reference.sh SUITE.yaml [--jobs N] [--bin PATH]"
case "${1:-}" in
  -h|--help) sed -n '2,6p' "$0"; exit 0 ;;
  ""|-*) echo "check_reference: $usage" >&2; exit 2 ;;
esac
suite="$1"
shift
[[ -f "$suite" ]] || { echo "check_reference: no suite file '$suite'" >&2; exit 2; }
jobs=$(nproc)
bin="build/bin/crowdsim-bench"
while [[ $# -gt 0 ]]; do
  case "$1" in
    --jobs|--bin)
      [[ $# -ge 2 ]] || { echo "check_reference: $1 needs a value ($usage)" >&2; exit 2; }
      if [[ "$1" == --jobs ]]; then jobs="$2"; else bin="$2"; fi
      shift 2 ;;
    *) echo "check_reference: unknown option '$1' ($usage)" >&2; exit 2 ;;
  esac
done
name=$(sed -n 's/^name: *\([A-Za-z0-9_.-]*\).*/\1/p' "$suite" | head -n1)
reference="results/$name/episodes.csv"
[[ -f "$reference" ]] || { echo "check_reference: no committed reference $reference" >&2; exit 2; }
out="runs/${name}_check"
log=$(mktemp)
trap 'rm -f "$log"' EXIT
"$bin" run "$suite" --out "$out" --fresh --jobs "$jobs" --quiet > /dev/null 2> "$log" || { cat "$log" >&2; exit 1; }
# decision_time_us, a wall-time measurement, is never reproduced. Parsed as CSV: a swept row's
# label may hold commas inside its quotes ("orca/kinematics={model: unicycle, accel_max: 1}").
strip() {
  python3 -c 'import csv, sys
rows = csv.reader(open(sys.argv[1], newline=""))
out = csv.writer(sys.stdout, lineterminator="\n")
head = next(rows)
skip = head.index("decision_time_us")
out.writerow(head[:skip] + head[skip + 1:])
for row in rows:
    out.writerow(row[:skip] + row[skip + 1:])' "$1"
}
if diff <(strip "$reference") <(strip "$out/episodes.csv") > "$out/differences.txt"; then
  echo "$suite: all $(($(wc -l < "$reference") - 1)) episodes identical to $reference"
else
  echo "$suite: differs from $reference ($(grep -c '^<' "$out/differences.txt") lines); see $out/differences.txt" >&2
  head -n 6 "$out/differences.txt" >&2
  exit 1
fi
