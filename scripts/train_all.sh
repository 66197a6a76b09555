#!/usr/bin/env bash
# Trains every training file (or those given) that has no finished training yet, N at a time,
# each at low priority (nice) on one core; an interrupted training is resumed from its
# checkpoint. Safe to rerun at any time: finished trainings are skipped (one whose file now
# asks for more RL episodes resumes from its last checkpoint and goes on to the new length).
#
#   scripts/train_all.sh [-j N] [--seeds "1010 2020 3030"] [--build DIR | --bin PATH]
#                        [FILE.yaml[@SEED] ...]
#
# Without files: suites/train/*.yaml. A file trains with its own seed into
# results/train/<name>/; FILE@SEED (or --seeds for every file) with another seed into
# results/train/<name>_seed<SEED>/. Trainings start in the order given. Each training's
# output goes to <out>/train.log. The trainings run from a frozen copy of the build (DIR,
# default build/): its install (programs, libraries, plugins, data; not the models) under
# results/train/.frozen/<time>-<commit>/, so that rebuilding during a campaign of hours
# changes no training that runs or waits. --bin PATH runs that program as it is instead.
set -euo pipefail

jobs=2
seeds=""
build="build"
bin=""
files=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    -j|--seeds|--build|--bin)
      [[ $# -ge 2 ]] || { echo "train_all: $1 needs a value (see --help)" >&2; exit 2; } ;;&
    -j) jobs="$2"; shift 2 ;;
    --seeds) seeds="$2"; shift 2 ;;
    --build) build="$2"; shift 2 ;;
    --bin) bin="$2"; shift 2 ;;
    -h|--help) sed -n '2,16p' "$0"; exit 0 ;;
    -*) echo "train_all: unknown option '$1' (see --help)" >&2; exit 2 ;;
    *) files+=("$1"); shift ;;
  esac
done
# xargs -P 0 would run every training at once.
[[ "$jobs" =~ ^[1-9][0-9]*$ ]] || { echo "train_all: -j takes a whole number >= 1, got '$jobs'" >&2; exit 2; }
[[ ${#files[@]} -gt 0 ]] || files=(suites/train/*.yaml)
if [[ -n "$bin" ]]; then
  [[ -x "$bin" ]] || { echo "train_all: '$bin' not found (--bin)" >&2; exit 2; }
else
  [[ -x "$build/bin/crowdsim-bench" && -f "$build/cmake_install.cmake" ]] ||
    { echo "train_all: no build in '$build'; run 'make build' first (or pass --build DIR)" >&2; exit 2; }
fi

# One line per training to run: FILE SEED OUT (SEED '-' = the file's own).
plan=()
declare -A entry_of_out=()
for entry in "${files[@]}"; do
  f="${entry%@*}"
  own_seeds="$seeds"
  if [[ "$entry" == *@* ]]; then
    own_seeds="${entry##*@}"
    [[ -n "$own_seeds" ]] || { echo "train_all: '$entry' has no seed after '@'" >&2; exit 2; }
  fi
  [[ -f "$f" ]] || { echo "train_all: no training file '$f'" >&2; exit 2; }
  name=$(sed -n 's/^name: *\([A-Za-z0-9_.-]*\).*/\1/p' "$f" | head -n1)
  [[ -n "$name" ]] || { echo "train_all: '$f' has no 'name:' line" >&2; exit 2; }
  for s in ${own_seeds:--}; do
    [[ "$s" == "-" || "$s" =~ ^[0-9]+$ ]] || { echo "train_all: seed '$s' of '$entry' is not a number" >&2; exit 2; }
    out="results/train/$name"
    [[ "$s" == "-" ]] || out="${out}_seed$s"
    # Two trainings in one folder: the second failed at the first's lock or checkpoint.
    if [[ -n "${entry_of_out[$out]:-}" ]]; then
      echo "train_all: '$entry' trains into $out, as '${entry_of_out[$out]}' does; give each training its own name: (or another seed)" >&2
      exit 2
    fi
    entry_of_out[$out]="$entry"
    if [[ -f "$out/weights.pt" ]] && grep -q '"finished": true' "$out/summary.json" 2>/dev/null; then
      # Finished, unless the file now asks for a longer RL phase: then it resumes and goes on.
      want=$(grep -o 'rl_episodes: *[0-9]*' "$f" | head -n1 | grep -o '[0-9]*$' || true)
      done_rl=$(grep -o '"rl_episodes": *[0-9]*' "$out/summary.json" | head -n1 | grep -o '[0-9]*$' || true)
      if [[ -z "$want" || "$want" == "$done_rl" ]]; then
        echo "train_all: $out is finished, skipped"
        continue
      fi
      echo "train_all: $out finished $done_rl RL episodes; the file asks for $want: lengthening it"
    fi
    plan+=("$f $s $out")
  done
done
[[ ${#plan[@]} -gt 0 ]] || { echo "train_all: nothing to train"; exit 0; }
echo "train_all: ${#plan[@]} training(s), $jobs at a time"
if [[ -z "$bin" ]]; then
  # Named after the commit the build was made from (as its manifests record it), not HEAD's.
  commit=$("$build/bin/crowdsim-bench" --version | sed -n 's/.*(commit \([^)]*\)).*/\1/p')
  frozen="results/train/.frozen/$(date -u +%Y%m%dT%H%M%SZ)-${commit:-unknown}"
  # The models are not part of it (component "models"): trainings do not read them.
  cmake --install "$build" --prefix "$frozen" --component Unspecified > /dev/null ||
    { echo "train_all: could not install '$build' into $frozen" >&2; exit 1; }
  bin="$frozen/bin/crowdsim-bench"
  echo "train_all: running a frozen copy of $build: $frozen"
fi

run_one() {
  local f="$1" s="$2" out="$3" bin="$4"
  local args=(train "$f" --out "$out" --quiet)
  [[ "$s" == "-" ]] || args+=(--seed "$s")
  [[ -f "$out/checkpoint/state.txt" || -f "$out/checkpoint.tmp/state.txt" ]] && args+=(--resume)
  mkdir -p "$out"
  echo "train_all: start $out ($(date -u +%H:%M:%S))"
  if nice -n 10 "$bin" "${args[@]}" >>"$out/train.log" 2>&1; then
    echo "train_all: done  $out ($(date -u +%H:%M:%S))"
  else
    echo "train_all: FAILED $out (exit $?), see $out/train.log" >&2
    return 1
  fi
}
export -f run_one
printf '%s\n' "${plan[@]}" | xargs -P "$jobs" -L 1 bash -c 'run_one "$0" "$1" "$2" "'"$bin"'"'
