#!/usr/bin/env bash
# `make bench` runs only Google Benchmarks: every file its loop takes from BUILD/bench/ accepts
# the benchmark flags and lists its benchmarks (it ran rvo2_overlap_stats, overlap_stats.sh's
# helper, which answered --benchmark_min_time with its usage), and every benchmark executable
# there is one the loop takes.
#   tests/docs/make_bench_targets_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build="$(cd "$1" && pwd)"
src="$(cd "$2" && pwd)"
# The loop's pattern, e.g. $(BUILD)/bench/*_bench.
pattern=$(sed -n 's/^\t.*for b in \$(BUILD)\/bench\/\([^;]*\); do.*/\1/p' "$src/Makefile")
[[ -n "$pattern" ]] || { echo "FAIL: no 'for b in \$(BUILD)/bench/...' loop in the Makefile's bench target"; exit 1; }
status=0
shopt -s nullglob
taken=("$build"/bench/$pattern)
[[ ${#taken[@]} -ge 5 ]] || { echo "FAIL: make bench would run only ${#taken[@]} files ($build/bench/$pattern)"; exit 1; }
for b in "${taken[@]}"; do
  if ! out=$("$b" --benchmark_list_tests --benchmark_min_time=0.2 2>&1) || [[ -z "$out" ]]; then
    echo "FAIL: make bench runs $b, which is not a Google Benchmark: $out"
    status=1
  fi
done
# Every executable linked with Google Benchmark is run.
for b in "$build"/bench/*; do
  [[ -x "$b" && -f "$b" ]] || continue
  in_loop=0
  for t in "${taken[@]}"; do [[ "$t" == "$b" ]] && in_loop=1; done
  if [[ $in_loop == 0 ]] && "$b" --benchmark_list_tests > /dev/null 2>&1; then
    echo "FAIL: $b is a benchmark that make bench does not run (the loop takes $pattern)"
    status=1
  fi
done
[[ $status == 0 ]] && echo "make bench runs the ${#taken[@]} benchmarks of $build/bench: ok"
exit $status
