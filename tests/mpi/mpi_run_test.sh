#!/usr/bin/env bash
# `mpirun -n 2 crowdsim-bench run` gives exactly the single-process episodes (timing aside), and
# a second launch resumes every episode from the ranks' folders.
#   tests/mpi/mpi_run_test.sh BUILD_DIR SOURCE_DIR MPIEXEC
set -euo pipefail
source "$(dirname "$0")/../support/cli_test.sh" "$@"
cd "$source"
"$mpiexec" "${mpi_flags[@]}" -n 2 "$bin" run suites/baselines.yaml --episodes 25 --jobs 1 --out "$work/mpi" \
  > "$work/mpi.log" 2>&1 || { cat "$work/mpi.log"; fail "mpirun -n 2 run"; }
grep -q "from 2 MPI ranks" "$work/mpi.log" || { cat "$work/mpi.log"; fail "not split over 2 ranks"; }
"$bin" run suites/baselines.yaml --episodes 25 --jobs 1 --out "$work/single" > "$work/single.log" 2>&1 ||
  { cat "$work/single.log"; fail "single-process run"; }
strip() { cut -d, -f1-11,13- "$1"; }
diff <(strip "$work/single/episodes.csv") <(strip "$work/mpi/episodes.csv") || fail "episodes differ"
diff <(cut -d, -f1-15,17- "$work/single/table.csv") <(cut -d, -f1-15,17- "$work/mpi/table.csv") || fail "tables differ"
"$mpiexec" "${mpi_flags[@]}" -n 2 "$bin" run suites/baselines.yaml --episodes 25 --jobs 1 --out "$work/mpi" \
  > "$work/again.log" 2>&1 || { cat "$work/again.log"; fail "second mpirun"; }
diff <(strip "$work/single/episodes.csv") <(strip "$work/mpi/episodes.csv") || fail "episodes differ after resuming"
# merge started by mpirun (a merge step in an MPI job script): one merge, exit 0 (every rank
# merged into the folder and all but one were refused by its lock: exit 2).
"$mpiexec" "${mpi_flags[@]}" -n 2 "$bin" merge "$work/mpi/ranks/1of2" "$work/mpi/ranks/2of2" \
  --out "$work/merged" > "$work/merge.log" 2>&1 || { cat "$work/merge.log"; fail "mpirun -n 2 merge"; }
# Counted as matches, not lines: mpirun forwards a rank's stdout (the table) and stderr (the
# "wrote" line) separately, and on a busy machine one lands inside a line of the other.
[[ $(grep -o "wrote [^ ]*/merged/table.md" "$work/merge.log" | wc -l) -eq 1 ]] ||
  { cat "$work/merge.log"; fail "not one merge"; }
diff <(strip "$work/single/episodes.csv") <(strip "$work/merged/episodes.csv") || fail "merged episodes differ"
# A merge that fails on rank 0 must not leave the other rank waiting: a usage error (--suite
# twice, which rank 0 alone once read) and a refusal (a folder that is not there) end the launch
# with exit 2, and its message.
for bad in "--suite suites/quick.yaml --suite suites/quick.yaml" "--suite suites/quick.yaml $work/none"; do
  status=0
  # shellcheck disable=SC2086  # $bad: several arguments
  timeout 120 "$mpiexec" "${mpi_flags[@]}" -n 2 "$bin" merge "$work/mpi/ranks/1of2" \
    "$work/mpi/ranks/2of2" --out "$work/merged_bad" $bad > "$work/merge_bad.log" 2>&1 || status=$?
  [[ $status -ne 124 ]] || { cat "$work/merge_bad.log"; fail "mpirun -n 2 merge $bad hung"; }
  [[ $status -ne 0 ]] || { cat "$work/merge_bad.log"; fail "mpirun -n 2 merge $bad succeeded"; }
  grep -q "error: " "$work/merge_bad.log" || { cat "$work/merge_bad.log"; fail "merge $bad said nothing"; }
done
# A rank whose run fails (here its manifest.json cannot be written: a folder holds its name)
# must not leave the others waiting in a collective call: the launch ends with exit 1 and says so.
mkdir -p "$work/broken/ranks/2of2/manifest.json/held"
head -n 1 results/quick/episodes.csv > "$work/broken/ranks/2of2/episodes.csv"
status=0
timeout 120 "$mpiexec" "${mpi_flags[@]}" -n 2 "$bin" run suites/quick.yaml --episodes 4 --quiet \
  --out "$work/broken" > "$work/broken.log" 2>&1 || status=$?
[[ $status -eq 1 ]] || { cat "$work/broken.log"; fail "a failing rank: exit $status, not 1 (124: hung)"; }
grep -q "error: rank 1:" "$work/broken.log" || { cat "$work/broken.log"; fail "the failing rank is not named"; }
# Refused everywhere (another configuration in every rank's folder): exit 2, nothing run.
status=0
"$mpiexec" "${mpi_flags[@]}" -n 2 "$bin" run suites/baselines.yaml --episodes 25 --jobs 1 --set seed=5 \
  --out "$work/mpi" > "$work/refused.log" 2>&1 || status=$?
[[ $status -eq 2 ]] || { cat "$work/refused.log"; fail "a refused launch: exit $status, not 2"; }
grep -q "the run was refused" "$work/refused.log" || { cat "$work/refused.log"; fail "not said refused"; }
echo "mpirun -n 2 run equals the single process: ok"
