#!/usr/bin/env bash
# scripts/train_all.sh trains from a frozen copy of the build (its install without the models,
# under results/train/.frozen/), so a rebuild during a campaign changes no training: the copy
# is made, runs on its own (its plugins, not the build's), trains the file to the end, and a
# relaunch with nothing left to train makes no second copy. Tiny budgets: this checks the
# campaign, not learning. Exit 77 (skipped) in a build without the learned policies.
#   tests/cli/train_all_freeze_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
source "$(dirname "$0")/../support/cli_test.sh" "$@"
[[ -f "$build/plugins/crowdsim_cadrl.so" ]] || { echo "no cadrl plugin (built without libtorch)"; exit 77; }
build_abs=$(cd "$build" && pwd)
cp -r "$source/suites" "$source/worlds" "$work/"
cat > "$work/suites/train/tiny.yaml" <<'YAML'
name: tiny
seed: 3
policy: cadrl
params: {sensors: person}
sensors: [person]
world: {source: random_rect, obstacles: 0, split: train}
humans: {count: 2, policy: orca}
training:
  il_episodes: 4
  il_epochs: 1
  rl_episodes: 4
  validation_interval: 2
  validation_episodes: 2
  checkpoint_interval: 2
YAML
cd "$work"
"$source/scripts/train_all.sh" -j 1 --build "$build_abs" suites/train/tiny.yaml > first.log 2>&1 ||
  { cat first.log; fail "train_all"; }
frozen=$(sed -n 's/^train_all: running a frozen copy of .*: //p' first.log)
[[ -n "$frozen" && -x "$frozen/bin/crowdsim-bench" ]] || { cat first.log; fail "no frozen copy"; }
[[ "$frozen" == results/train/.frozen/* ]] || fail "frozen copy outside results/train/.frozen: $frozen"
[[ ! -e "$frozen/share/crowdsim-bench/results" ]] || fail "the frozen copy holds the models"
"$frozen/bin/crowdsim-bench" list-plugins > plugins.txt 2>&1 || { cat plugins.txt; fail "list-plugins"; }
grep -q "file: $work/$frozen/lib/crowdsim-bench/plugins/crowdsim_cadrl.so" plugins.txt ||
  { cat plugins.txt; fail "the frozen copy does not load its own cadrl plugin"; }
grep -q '"finished": true' results/train/tiny/summary.json || { cat first.log; fail "tiny did not finish"; }
"$source/scripts/train_all.sh" -j 1 --build "$build_abs" suites/train/tiny.yaml > again.log 2>&1 ||
  { cat again.log; fail "second train_all"; }
grep -q "results/train/tiny is finished, skipped" again.log || { cat again.log; fail "a relaunch retrained"; }
[[ $(ls results/train/.frozen | wc -l) == 1 ]] || fail "a relaunch with nothing to train made another copy"
echo "train_all trains from a frozen copy of the build: ok"
