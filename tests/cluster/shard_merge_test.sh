#!/usr/bin/env bash
# `run --shard K/3` for K = 1, 2, 3 and `merge` reproduce a single run of the committed suites
# quick and baselines: table.md, table.csv and episodes.csv equal in full, but for the timing
# columns (found by their header names). A changed file must fail the comparison (checked).
#   tests/cluster/shard_merge_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
source "$(dirname "$0")/../support/cli_test.sh" "$@"
cd "$source"

# The timing columns: episodes.csv's decision_time_us, the tables' "decision µs" (the
# per-decision wall time of the policy; everything else is a result of the seeded episodes).
timing_columns='decision_time_us|decision µs'

# without_timing FILE: FILE with the timing columns removed. CSV fields may be quoted (a
# quoted field keeps its commas); in a Markdown table every block of '|' lines has its header
# first. Fails if the file has no timing column at all (a renamed column must not silently
# turn the comparison into one that compares the timings too).
without_timing() {
  awk -v names="$timing_columns" -v md="$([[ $1 == *.md ]] && echo 1 || echo 0)" '
    function split_csv(line, f,    n, i, c, quoted, cur) {
      n = 0; cur = ""; quoted = 0
      for (i = 1; i <= length(line); i++) {
        c = substr(line, i, 1)
        if (c == "\"") quoted = !quoted
        if (c == "," && !quoted) { f[++n] = cur; cur = "" } else cur = cur c
      }
      f[++n] = cur
      return n
    }
    function trim(s) { gsub(/^ +| +$/, "", s); return s }
    function is_timing(name,    k, i) {
      k = split(names, list, "|")
      for (i = 1; i <= k; i++) if (trim(name) == list[i]) return 1
      return 0
    }
    BEGIN { found = 0 }
    md && !/^\|/ { in_table = 0; print; next }
    {
      if (md) { n = split($0, f, "|") } else { n = split_csv($0, f) }
      if ((md && !in_table) || (!md && NR == 1)) {
        delete drop
        for (i = 1; i <= n; i++) if (is_timing(f[i])) { drop[i] = 1; found = 1 }
        in_table = 1
      }
      out = ""; first = 1
      for (i = 1; i <= n; i++) {
        if (i in drop) continue
        out = out (first ? "" : (md ? "|" : ",")) f[i]; first = 0
      }
      print out
    }
    END { if (!found) { print "no timing column (" names ") in " FILENAME > "/dev/stderr"; exit 3 } }
  ' "$1"
}

# same_results A B: A's and B's tables and episodes are equal but for timing; names the file.
same_results() {
  local f
  for f in table.md table.csv episodes.csv; do
    [[ -s "$1/$f" && -s "$2/$f" ]] || { echo "missing $f in $1 or $2" >&2; return 1; }
    without_timing "$1/$f" > "$work/a" && without_timing "$2/$f" > "$work/b" || return 1
    diff "$work/a" "$work/b" >&2 || { echo "$f differs" >&2; return 1; }
  done
}

# suite EPISODES: a single run and three shards (their --jobs differ on purpose), merged.
check_suite() {
  local suite="$1" episodes="$2" name k
  name=$(basename "$suite" .yaml)
  "$bin" run "$suite" --episodes "$episodes" --jobs 2 --quiet --out "$work/$name/single" \
    > "$work/$name.single.log" 2>&1 || { cat "$work/$name.single.log"; fail "$name: single run"; }
  for k in 1 2 3; do
    "$bin" run "$suite" --episodes "$episodes" --jobs 1 --quiet --shard "$k/3" --out "$work/$name/shard$k" \
      > "$work/$name.shard$k.log" 2>&1 || { cat "$work/$name.shard$k.log"; fail "$name: shard $k/3"; }
    [[ ! -e "$work/$name/shard$k/table.md" ]] || fail "$name: shard $k/3 wrote a table"
  done
  "$bin" merge "$work/$name/shard1" "$work/$name/shard2" "$work/$name/shard3" --out "$work/$name/merged" \
    > "$work/$name.merge.log" 2>&1 || { cat "$work/$name.merge.log"; fail "$name: merge"; }
  local total
  total=$(($(wc -l < "$work/$name/single/episodes.csv") - 1))
  grep -q "($total episodes from 3 folders)" "$work/$name.merge.log" ||
    { cat "$work/$name.merge.log"; fail "$name: merge did not join the $total episodes"; }
  same_results "$work/$name/single" "$work/$name/merged" || fail "$name: merged shards differ from the single run"
  echo "$name: 3 shards of $total episodes merge into the single run"
}

# quick in full (its 100 episodes: under a second); baselines (6 rows, OMPL planner) capped at
# 50 of its 500 episodes to stay within seconds. Neither count is a multiple of 3, so the
# slices cut across rows differently in every row.
check_suite suites/quick.yaml 100
check_suite suites/baselines.yaml 50

# The comparison fails on a change: one outcome in episodes.csv, one rate in table.csv, one
# cell of table.md; and it ignores a changed timing value.
changed="$work/changed"
mutate() {  # mutate FILE SED_EXPRESSION: a copy of the merged quick run with FILE edited
  rm -rf "$changed"; cp -r "$work/quick/merged" "$changed"
  sed -i "$2" "$changed/$1"
  cmp -s "$changed/$1" "$work/quick/merged/$1" && fail "the edit of $1 changed nothing"
  return 0
}
# The decision time of the first episode, found by its header name (the line has no quoted field).
column=$(head -n1 "$work/quick/merged/episodes.csv" | tr ',' '\n' | grep -n -x decision_time_us | cut -d: -f1)
mutate episodes.csv "2s/^\(\([^,]*,\)\{$((column - 1))\}\)[^,]*/\19999.000/"
same_results "$work/quick/single" "$changed" 2>/dev/null || fail "a changed decision time is not ignored"
mutate episodes.csv '3s/,\(collision_[a-z]*\|success\|timeout\),/,policy_error,/'
same_results "$work/quick/single" "$changed" 2>/dev/null && fail "a changed outcome in episodes.csv passed"
mutate table.csv '2s/,0\.\([0-9]\)/,1.\1/'
same_results "$work/quick/single" "$changed" 2>/dev/null && fail "a changed rate in table.csv passed"
mutate table.md '3s/| 100 |/| 99 |/'
same_results "$work/quick/single" "$changed" 2>/dev/null && fail "a changed cell of table.md passed"
echo "the comparison catches changed results and ignores timing: ok"
