#!/usr/bin/env bash
# Runs every command of the shell blocks of README.md, CONTRIBUTING.md and docs/*.md, on small
# budgets, and the script that redraws their figures, so the pages cannot drift from the program.
#
#   tests/docs/readme_commands_test.sh BUILD_DIR SOURCE_DIR [PYTHON]
#
# Taken: each line of a ```sh block that starts with build/bin/, mpirun, for, source or
# PYTHONPATH=build/python (run with PYTHON, the interpreter the package was built
# for; skipped without it), page by page, each page top to bottom. The `make` lines are what CI
# runs anyway. Budgets: every `run` gets --episodes 3, every `train` a few imitation and RL
# episodes, the PyTorch example 10 updates (skipped without python3-torch). The commands run in
# order in a scratch copy of the checkout's suites, worlds and examples, with the committed
# results linked in (read only), so they write nothing into the checkout. mpirun lines are
# skipped when the CLI was built without MPI.
set -uo pipefail

build="$(cd "$1" && pwd)"
src="$(cd "$2" && pwd)"
python="${3:-}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cp -r "$src/suites" "$src/worlds" "$src/examples" "$work/"
mkdir -p "$work/results" "$work/build"
for r in "$src"/results/*; do
  [[ "$(basename "$r")" == train ]] || ln -s "$r" "$work/results/$(basename "$r")"  # local trainings stay out
done
for d in "$build"/*; do ln -s "$d" "$work/build/$(basename "$d")"; done

# The pages: the README, the contributing guide and every docs page. Each page's commands run in
# its own order; a page must not depend on another page's outputs.
pages=("$src/README.md")
[[ -f "$src/CONTRIBUTING.md" ]] && pages+=("$src/CONTRIBUTING.md")
for p in "$src"/docs/*.md; do [[ -f "$p" ]] && pages+=("$p"); done
commands=()
for p in "${pages[@]}"; do
  mapfile -t page_commands < <(awk '
    /^```/ { sh = ($0 ~ /^```sh/) && !sh; next }
    sh { line = $0; sub(/^[ \t]+/, "", line)
         if (line ~ /^(build\/bin\/|mpirun |for |source |PYTHONPATH=build\/python )/) { sub(/[ \t]+#.*$/, "", line); print line } }' \
    "$p")
  echo "${p#"$src"/}: ${#page_commands[@]} commands"
  commands+=("${page_commands[@]}")
done
# The README alone had 30 commands before they moved to the docs pages: every one stays tested.
[[ ${#commands[@]} -ge 30 ]] || { echo "FAIL: found only ${#commands[@]} commands in ${#pages[@]} pages"; exit 1; }
[[ -f "$src/docs/usage.md" ]] || { echo "FAIL: docs/usage.md, the page of the CLI's commands, is missing"; exit 1; }

small_ppo='--set total_steps=128 --set num_envs=2 --set steps_per_rollout=32 --set minibatch_size=32 --set checkpoint_interval=1'
small_train='--set training.il_episodes=3 --set training.il_epochs=1 --set training.rl_episodes=2 --set training.validation_interval=2 --set training.validation_episodes=2 --set training.checkpoint_interval=2'
with_mpi=0
"$build/bin/crowdsim-bench" --version | grep -q "with MPI" && command -v mpirun >/dev/null && with_mpi=1
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1

failed=0
ran=0
for c in "${commands[@]}"; do
  if [[ "$c" == mpirun* && $with_mpi == 0 ]]; then
    echo "SKIP (built without MPI): $c"
    continue
  fi
  if [[ "$c" == PYTHONPATH=* ]]; then
    if [[ -z "$python" ]]; then
      echo "SKIP (no Python package built): $c"
      continue
    fi
    c="${c/ \/usr\/bin\/python3 / $python }"
    # docs/gymnasium.md's commands run in a venv with gymnasium (not a Debian 12 package).
    if [[ "$c" == *"~/venv-gym/bin/python"* ]] && [[ ! -x "$HOME/venv-gym/bin/python" ]]; then
      echo "SKIP (no ~/venv-gym with gymnasium, docs/gymnasium.md): $c"
      continue
    fi
    if [[ "$c" == *_torch.py* ]] && ! "$python" -c "import torch" 2>/dev/null; then
      echo "SKIP (no python3-torch): $c"
      continue
    fi
  fi
  cmd=$(sed -E -e 's/ --episodes [0-9]+//g' \
               -e 's/(crowdsim-bench run [^ ]+)/\1 --episodes 3/g' \
               -e 's/(train_policy_torch\.py) [0-9]+/\1 10/' \
               -e "s/(crowdsim-bench train [^ ]+)/\\1 $small_train/g" \
               -e "s/(crowdsim_bench\.ppo train [^ ]+)/\\1 $small_ppo/g" <<<"$c")
  echo "RUN  $cmd"
  if ! out=$(cd "$work" && timeout 300 bash -c "$cmd" 2>&1); then
    echo "FAIL: $c"
    echo "$out" | tail -n 15 | sed 's/^/    /'
    failed=$((failed + 1))
  fi
  ran=$((ran + 1))
done
# The README's picture and the gallery (docs/gallery.md) are redrawn from the committed results by a script:
# it must run too (into the scratch folder).
echo "RUN  scripts/make_gallery.sh"
if ! out=$(cd "$src" && timeout 300 bash scripts/make_gallery.sh --bin "$build/bin/crowdsim-bench" --out "$work/docs" 2>&1); then
  echo "FAIL: scripts/make_gallery.sh"
  echo "$out" | tail -n 15 | sed 's/^/    /'
  failed=$((failed + 1))
fi
ran=$((ran + 1))
for f in episode.png gallery/success.png gallery/collision_human.png gallery/collision_obstacle.png \
         gallery/timeout.png gallery/floorplan.png gallery/lidar.png gallery/compare.png gallery/ppo_wall.png; do
  [[ -s "$work/docs/$f" ]] || { echo "FAIL: make_gallery.sh wrote no docs/$f"; failed=$((failed + 1)); }
done
echo "$ran commands of ${#pages[@]} pages run, $failed failed"
[[ $failed == 0 ]]
