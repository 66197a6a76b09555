#!/usr/bin/env bash
# Fuzzes the readers of user-written files (suites, world files, training files) and of the files
# a run leaves (episodes.csv, manifest.json) or loads (plugin files' headers; the targets are
# listed in tests/fuzz/fuzz_targets.cc) with libFuzzer, AddressSanitizer and UBSan: configures a
# clang build in build-fuzz/ (CROWDSIM_FUZZ=ON; only the core, the plugins and the fuzzers are
# built), then runs each target for a bounded time, nice'd, starting from its committed corpus
# tests/fuzz/corpus/<target>/. New inputs go to build-fuzz/fuzz-corpus/<target>/; a crash, hang,
# leak or UB is saved under build-fuzz/fuzz-artifacts/<target>/ and the script exits 1.
#
# Usage: scripts/fuzz.sh [SECONDS] [--target NAME]... [--update-corpus] [--reseed]
#   SECONDS          fuzzing time per target (default 60)
#   --target NAME    only this target (repeatable): suite_reader, world_reader, training_reader,
#                    episodes_reader, manifest_reader, plugin_file
#   --update-corpus  afterwards, add to the committed corpus the new inputs that reach new code
#                    (libFuzzer -merge=1: nothing already there is removed)
#   --reseed         first add to the committed corpus the seeds made from the project's files
#                    (tests/fuzz/make_seeds.py: suites/, suites/train/, worlds/) that reach new code
# Environment: CC/CXX are not used; CLANGXX (default clang++), JOBS (build jobs, default nproc),
#   FUZZ_NICE (default 10), FUZZ_BUILD (default build-fuzz).
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
build=${FUZZ_BUILD:-$root/build-fuzz}
seconds=60
update=0
reseed=0
targets=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --target) targets+=("$2"); shift 2 ;;
    --update-corpus) update=1; shift ;;
    --reseed) reseed=1; shift ;;
    ''|*[!0-9]*) echo "fuzz.sh: unknown argument '$1' (usage: scripts/fuzz.sh [SECONDS] [--target NAME]... [--update-corpus] [--reseed])" >&2; exit 2 ;;
    *) seconds=$1; shift ;;
  esac
done
[[ ${#targets[@]} -gt 0 ]] ||
  targets=(suite_reader world_reader training_reader episodes_reader manifest_reader plugin_file)

clangxx=${CLANGXX:-clang++}
if ! command -v "$clangxx" >/dev/null; then
  echo "fuzz.sh: $clangxx not found; install clang and libFuzzer: scripts/install_deps.sh --fuzz" >&2
  exit 2
fi

cmake -S "$root" -B "$build" -DCMAKE_CXX_COMPILER="$clangxx" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCROWDSIM_FUZZ=ON -DCROWDSIM_WITH_TORCH=OFF -DCROWDSIM_BUILD_TESTS=OFF \
  -DCROWDSIM_BUILD_BENCHMARKS=OFF -DCROWDSIM_WITH_PYTHON=OFF -DCROWDSIM_WITH_MPI=OFF >/dev/null
cmake --build "$build" --target crowdsim_fuzzers -j "${JOBS:-$(nproc)}"

corpus_root="$root/tests/fuzz/corpus"
if [[ $reseed -eq 1 ]]; then
  rm -rf "$build/fuzz-seeds"
  /usr/bin/env python3 "$root/tests/fuzz/make_seeds.py" "$root" "$build/fuzz-seeds"
fi

# Leaks are findings too; the plugins stay loaded (one registry per process), so unloading them
# at exit must not hide the stacks.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:fast_unwind_on_malloc=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1}
# Inputs (and corpus files) of at most 4 KB: a suite's structure fits, and the committed corpus
# stays a few hundred KB.
max_len=4096
failed=()
for t in "${targets[@]}"; do
  fuzzer="$build/fuzz/${t}_fuzz"
  [[ -x $fuzzer ]] || { echo "fuzz.sh: no fuzz target '$t' ($fuzzer)" >&2; exit 2; }
  committed="$corpus_root/$t"
  work="$build/fuzz-corpus/$t"
  artifacts="$build/fuzz-artifacts/$t"
  mkdir -p "$committed" "$work" "$artifacts" "$build/fuzz-logs"
  if [[ $reseed -eq 1 ]]; then
    "$fuzzer" -merge=1 -timeout=10 -max_len="$max_len" "$committed" "$build/fuzz-seeds/$t" 2>&1 | tail -n 1
  fi
  echo "== $t: ${seconds} s over $(ls "$committed" | wc -l) committed inputs"
  rc=0
  dict=()  # YAML's tokens help the YAML readers only
  case $t in suite_reader|world_reader|training_reader) dict=(-dict="$root/tests/fuzz/yaml.dict") ;; esac
  nice -n "${FUZZ_NICE:-10}" "$fuzzer" "$work" "$committed" -max_total_time="$seconds" -timeout=10 \
    -rss_limit_mb=2048 -max_len="$max_len" "${dict[@]}" -artifact_prefix="$artifacts/" \
    -print_final_stats=1 >"$build/fuzz-logs/$t.log" 2>&1 || rc=$?
  grep -E '^stat::(number_of_executed_units|average_exec_per_sec|new_units_added|peak_rss_mb)' \
    "$build/fuzz-logs/$t.log" || true
  if [[ $rc -ne 0 ]]; then
    failed+=("$t")
    echo "   FOUND A PROBLEM (exit $rc): $build/fuzz-logs/$t.log; input(s): $(ls "$artifacts")"
    grep -m1 -E 'ERROR: |runtime error|broke its contract|terminate called' "$build/fuzz-logs/$t.log" || true
  elif [[ $update -eq 1 ]]; then
    "$fuzzer" -merge=1 -timeout=10 -max_len="$max_len" "$committed" "$work" 2>&1 | tail -n 1
  fi
done

if [[ ${#failed[@]} -gt 0 ]]; then
  echo "fuzz.sh: problems found by ${failed[*]} (reproduce: build-fuzz/fuzz/<target>_fuzz <input>)" >&2
  exit 1
fi
echo "fuzz.sh: no problem found"
