#!/usr/bin/env bash
# The CLI with a plugin given by path that crashes or hangs (isolation on by default): the run
# exits 0, stderr names row, episode, plugin and signal, table.md counts the crash, a resume
# runs nothing again; Ctrl-C on an isolated run stops it as before (130, resume message) and
# leaves no worker process behind.
set -euo pipefail
source "$(dirname "$0")/../support/cli_test.sh" "$@"
plugin="$(cd "$build" && pwd)/tests/fixture_plugins/crowdsim_throwing_policy.so"

suite() {  # NAME MODE [EXTRA TOP-LEVEL LINE]
  cat > "$work/$1.yaml" <<YAML
name: $1
episodes: 4
seed: 5
${3:-}
world: {source: random_rect, obstacles: 1}
humans: {count: 2, policy: linear}
rows:
  - {label: bad, policy: $plugin, params: {mode: $2, fail_after_steps: 0}}
  - {label: good, policy: linear}
YAML
}

suite crash segfault
"$bin" run "$work/crash.yaml" --out "$work/crash" --jobs 2 --quiet > "$work/out.txt" 2> "$work/err.txt" ||
  fail "the run with a crashing plugin exited $? ($(cat "$work/err.txt"))"
grep -qF "row 'bad', episode 0 (rows[0]): worker process killed by signal SIGSEGV (Segmentation fault) while running policy 'throwing_policy' ($plugin); recorded as policy_crash" "$work/err.txt" ||
  fail "no message naming row, episode, plugin and signal: $(cat "$work/err.txt")"
grep -q "| crashes | hangs |" "$work/crash/table.md" || fail "table.md has no crashes column"
[[ $(grep -c ",policy_crash," "$work/crash/episodes.csv") -ge 1 ]] || fail "episodes.csv has no policy_crash line"
grep -q '"isolated": true' "$work/crash/manifest.json" || fail "a plugin given by path did not run isolated"
"$bin" run "$work/crash.yaml" --out "$work/crash" --jobs 2 --quiet > /dev/null 2> "$work/err2.txt" ||
  fail "the resume exited $?"
grep -q "(0 episodes run, 8 resumed)" "$work/err2.txt" || fail "the resume ran episodes again: $(cat "$work/err2.txt")"

suite hang hang "episode_timeout_s: 0.5"
"$bin" run "$work/hang.yaml" --out "$work/hang" --jobs 2 --quiet > /dev/null 2> "$work/err.txt" ||
  fail "the run with a hanging plugin exited $?"
grep -q "killed at the episode_timeout_s of 0.5 s while running policy 'throwing_policy'" "$work/err.txt" ||
  fail "no timeout message: $(cat "$work/err.txt")"
[[ $(grep -c ",policy_timeout," "$work/hang/episodes.csv") -ge 1 ]] || fail "episodes.csv has no policy_timeout line"

# Ctrl-C: a hang without a timeout, interrupted.
suite forever hang
"$bin" run "$work/forever.yaml" --out "$work/forever" --jobs 2 --quiet > /dev/null 2> "$work/err.txt" &
pid=$!
for _ in $(seq 50); do [[ $(pgrep -c -P "$pid") -ge 2 ]] && break; sleep 0.1; done
workers=$(pgrep -P "$pid" | tr '\n' ' ')
[[ -n "$workers" ]] || fail "no worker processes under the run"
kill -INT "$pid"
status=0
wait "$pid" || status=$?
[[ $status -eq 130 ]] || fail "Ctrl-C: exit status $status, expected 130"
grep -q "interrupted: the finished episodes are kept" "$work/err.txt" || fail "Ctrl-C: no resume message"
# Workers die with the run (a zombie until reaped counts as ended); allow a loaded machine 5 s.
running() { local stat; stat=$(ps -o stat= -p "$1" 2> /dev/null) && [[ $stat != Z* ]]; }
for w in $workers; do
  for _ in $(seq 50); do running "$w" || break; sleep 0.1; done
  running "$w" && fail "worker $w still runs 5 s after Ctrl-C"
done
echo "crash isolation CLI: ok"
