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
echo "mpirun -n 2 run equals the single process: ok"
