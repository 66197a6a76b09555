#!/usr/bin/env bash
# scripts/check_reference.sh reruns a suite and finds its committed episodes identical, the
# decision time aside, also where a swept row's label holds commas inside its CSV quotes (a
# kinematics map: cut -d, took a label's half for a column and compared the decision times,
# which never repeat). A changed outcome is still found.
#   tests/cli/check_reference_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
source "$(dirname "$0")/../support/cli_test.sh" "$@"
cd "$work"
cat > commas.yaml <<'YAML'
name: commas
episodes: 6
seed: 3
world: {source: random_rect, obstacles: 1, split: test}
humans: {count: 3, policy: orca}
rows:
  - label: orca
    policy: orca
    sweep: {kinematics: [unicycle, {model: unicycle, accel_max: 1, angular_accel_max: 2}]}
YAML
"$bin" run commas.yaml --out results/commas --quiet > /dev/null 2>&1
grep -q '"orca/kinematics={model: unicycle, accel_max: 1' results/commas/episodes.csv ||
  fail "no quoted label with commas in episodes.csv"
"$source/scripts/check_reference.sh" commas.yaml --jobs 1 --bin "$bin" > out.log 2>&1 ||
  { cat out.log; fail "a rerun of the same suite was found to differ"; }
grep -q "all 12 episodes identical" out.log || { cat out.log; fail "unexpected report"; }
# One outcome changed by hand: found, exit 1.
sed -i '0,/,success,/s//,timeout,/' results/commas/episodes.csv
grep -q ',timeout,' results/commas/episodes.csv || fail "the test's edit found no success to change"
rc=0
"$source/scripts/check_reference.sh" commas.yaml --jobs 1 --bin "$bin" > out.log 2>&1 || rc=$?
[[ $rc == 1 ]] || { cat out.log; fail "a changed outcome was not found (exit $rc)"; }
grep -q "differs from results/commas/episodes.csv" out.log || { cat out.log; fail "no report"; }
echo "check_reference: ok"
