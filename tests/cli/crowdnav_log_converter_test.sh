#!/usr/bin/env bash
# examples/crowdnav_to_episode_log.py turns a CrowdNav episode dump into an episode log that
# `crowdsim-bench score` reads: a robot driving 4 m straight at 1 m/s past a standing person.
#   tests/cli/crowdnav_log_converter_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
source "$(dirname "$0")/../support/cli_test.sh" "$@"
cd "$work"
python3 - <<'PY'
import json
states = [{"robot": [k * 0.25, 0.0, 1.0 if k else 0.0, 0.0, 0.3, 4.0, 0.0, 0.0],
           "humans": [[2.0, 1.0, 0.0, 0.0, 0.3]]} for k in range(17)]
json.dump({"time_step": 0.25, "kinematics": "holonomic", "outcome": "ReachGoal", "states": states},
          open("episode.json", "w"))
PY
python3 "$source/examples/crowdnav_to_episode_log.py" episode.json --out episode.jsonl.gz
"$bin" score episode.jsonl.gz --out scores.csv 2> score.err || { cat score.err; fail "score exited $?"; }
grep -q "1 of 1 log(s) scored" score.err || fail "score did not score the log: $(cat score.err)"
# Straight 4 m to a goal 4 m away: SPL 1; from rest to 1 m/s in one step: accel. max 4 m/s^2.
python3 - <<'PY' || fail "unexpected scores: $(cat scores.csv)"
import csv
row = next(csv.DictReader(open("scores.csv")))
assert row["status"] == "success", row
assert abs(float(row["spl"]) - 1.0) < 1e-6, row
assert abs(float(row["accel_max"]) - 4.0) < 1e-6, row
assert int(row["personal_intrusions"]) == 1, row  # within 1.2 m of the person near x = 2
PY
# A dump with an unknown outcome is refused by the converter.
sed 's/ReachGoal/Lost/' episode.json > bad.json
if python3 "$source/examples/crowdnav_to_episode_log.py" bad.json --out bad.jsonl.gz 2> bad.err; then
  fail "the converter took an unknown outcome"
fi
grep -q "unknown outcome 'Lost'" bad.err || fail "unclear error: $(cat bad.err)"
echo "ok"
