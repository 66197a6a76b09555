#!/usr/bin/env bash
# `mpirun -n 2 crowdsim-bench train-all` trains a two-model campaign one model per rank, with
# exactly the weights and logs of the same campaign in one process, and a relaunch skips the
# finished trainings. Tiny budgets (a few episodes): this checks the campaign, not learning.
#   tests/mpi/mpi_train_test.sh BUILD_DIR SOURCE_DIR MPIEXEC
set -euo pipefail
source "$(dirname "$0")/../support/cli_test.sh" "$@"
campaign=(suites/train/cadrl_pp_lidar_rect0.yaml suites/train/sarl_person_rect0.yaml@7)
small=(--quiet --set training.il_episodes=4 --set training.il_epochs=1 --set training.rl_episodes=4
       --set training.validation_interval=2 --set training.validation_episodes=2
       --set training.checkpoint_interval=2)
for d in mpi single; do
  mkdir -p "$work/$d"
  cp -r "$source/suites" "$source/worlds" "$work/$d/"
done
(cd "$work/mpi" && "$mpiexec" "${mpi_flags[@]}" -n 2 "$bin" train-all "${campaign[@]}" "${small[@]}") \
  > "$work/mpi.log" 2>&1 || { cat "$work/mpi.log"; fail "mpirun -n 2 train-all"; }
grep -q "rank 0 of 2: suites/train/cadrl_pp_lidar_rect0.yaml" "$work/mpi.log" &&
  grep -q "rank 1 of 2: suites/train/sarl_person_rect0.yaml@7" "$work/mpi.log" ||
  { cat "$work/mpi.log"; fail "the two trainings were not split over the two ranks"; }
(cd "$work/single" && "$bin" train-all "${campaign[@]}" "${small[@]}") > "$work/single.log" 2>&1 ||
  { cat "$work/single.log"; fail "single-process train-all"; }
for model in cadrl_pp_lidar_rect0 sarl_person_rect0_seed7; do
  for f in weights.pt il.pt training_log.csv; do
    a="$work/mpi/results/train/$model/$f"; b="$work/single/results/train/$model/$f"
    [[ -s "$a" && -s "$b" ]] || fail "$model/$f missing"
    cmp -s "$a" "$b" || fail "$model/$f differs between mpirun -n 2 and one process"
  done
done
(cd "$work/mpi" && "$mpiexec" "${mpi_flags[@]}" -n 2 "$bin" train-all "${campaign[@]}" "${small[@]}") \
  > "$work/again.log" 2>&1 || { cat "$work/again.log"; fail "second mpirun"; }
[[ $(grep -c "finished already" "$work/again.log") == 2 ]] || { cat "$work/again.log"; fail "a relaunch retrained"; }
echo "mpirun -n 2 train-all equals the single process, and a relaunch skips finished trainings: ok"
