#!/usr/bin/env bash
# RVO2's own C++ against ours on RVO2's example scenarios (issue 14: Circle with 250 agents and
# Blocks with 100, >= 2x per step). Needs a checkout of RVO2 (github.com/snape/RVO2), which is
# not part of this repository. Its Circle.cc and Blocks.cc are built as its own build would
# (g++ -O2 -DNDEBUG, no OpenMP: one thread, as our benchmark), with the position output off and
# Blocks' random generator unseeded (the same run every time). A second build with the output
# on counts each example's steps (one output line per step) and gives its worst overlap, to set
# beside ours (the benchmark's counters). Then, ROUNDS times, each RVO2
# example runs as a whole process (time per step = its CPU time / its steps; its set-up is
# microseconds) alternated with our build/bench/rvo2_scenarios_bench (its per_step counter,
# CPU time per step).
#
#   tests/bench/orca/compare_rvo2.sh RVO2_DIR [ROUNDS]
# Run from the repository root after a Release build (build/bench/rvo2_scenarios_bench).
set -euo pipefail
rvo2="$(cd "${1:?usage: compare_rvo2.sh RVO2_DIR [ROUNDS]}" && pwd)"
rounds="${2:-3}"
bench=build/bench/rvo2_scenarios_bench
[[ -x "$bench" ]] || { echo "compare_rvo2: $bench not built (make bench)" >&2; exit 2; }
for f in src/RVOSimulator.cc examples/Circle.cc examples/Blocks.cc; do
  [[ -f "$rvo2/$f" ]] || { echo "compare_rvo2: '$rvo2' has no $f (not an RVO2 checkout?)" >&2; exit 2; }
done
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
# The worst overlap of a run printed by an example built with its output on: each line is the
# time, then every agent's position "(x,y)" (6 significant digits: ~1e-4 m at 100 m); the
# deepest pairwise penetration 2 r - distance over all lines, or 0 (all agents of radius r).
cat > "$work/worst_overlap.cc" <<'CC'
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>
int main(int argc, char** argv) {
  const double r = std::atof(argv[1]);
  double worst = 0.0;
  std::string line;
  std::vector<double> x, y;
  while (std::getline(std::cin, line)) {
    x.clear();
    y.clear();
    for (std::size_t at = line.find('('); at != std::string::npos; at = line.find('(', at + 1)) {
      double px, py;
      if (std::sscanf(line.c_str() + at, "(%lf,%lf)", &px, &py) == 2) {
        x.push_back(px);
        y.push_back(py);
      }
    }
    for (std::size_t i = 0; i < x.size(); ++i)
      for (std::size_t j = i + 1; j < x.size(); ++j)
        worst = std::max(worst, 2.0 * r - std::hypot(x[i] - x[j], y[i] - y[j]));
  }
  std::printf("%.3f\n", worst);
}
CC
g++ -O2 -std=c++17 "$work/worst_overlap.cc" -o "$work/worst_overlap"
declare -A steps overlap
declare -A radius=([Circle]=1.5 [Blocks]=2)
for example in Circle Blocks; do
  for output in 0 1; do
    g++ -O2 -DNDEBUG -std=c++17 -DRVO_OUTPUT_TIME_AND_POSITIONS=$output \
      -DRVO_SEED_RANDOM_NUMBER_GENERATOR=0 -I"$rvo2/src" "$rvo2/examples/$example.cc" \
      "$rvo2"/src/*.cc -o "$work/$example$output"
  done
  "$work/${example}1" > "$work/$example.out"
  steps[$example]=$(wc -l < "$work/$example.out")
  overlap[$example]=$("$work/worst_overlap" "${radius[$example]}" < "$work/$example.out")
done
echo "RVO2 at $(git -C "$rvo2" rev-parse --short HEAD 2>/dev/null || echo '?'):" \
  "Circle ${steps[Circle]} steps, worst overlap ${overlap[Circle]} m;" \
  "Blocks ${steps[Blocks]} steps, worst overlap ${overlap[Blocks]} m"
echo "ours: $("$bench" --benchmark_min_time=0.01 2>/dev/null |
  awk '/^BM_/ { printf "%s", $1; for (i = 2; i <= NF; ++i) if ($i ~ /^(steps|worst_overlap_m)=/) printf " %s", $i; printf "; " }')"
# CPU seconds (user + system) of one whole run of $1, as our benchmark counts CPU time.
seconds() {
  local TIMEFORMAT='%3U %3S' t
  t=$({ time "$1" > /dev/null; } 2>&1)
  awk -v t="$t" 'BEGIN { split(t, x, " "); printf "%.3f\n", x[1] + x[2] }'
}
# Our per-step time of benchmark $1 (circle250 or blocks100), in microseconds.
ours() {
  "$bench" --benchmark_filter="/$1\$" --benchmark_min_time=0.5 --benchmark_format=csv 2>/dev/null |
    awk -F, -v name="BM_Rvo2Example/$1" '
      NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "\"per_step\"" || $i == "per_step") col = i }
      $1 == "\"" name "\"" || $1 == name { printf "%.1f\n", $col * 1e6 }'
}
for ((r = 1; r <= rounds; r++)); do
  for pair in "Circle circle250" "Blocks blocks100"; do
    read -r example ours_name <<< "$pair"
    s=$(seconds "$work/${example}0")
    theirs_us=$(awk -v s="$s" -v n="${steps[$example]}" 'BEGIN { printf "%.1f\n", s * 1e6 / n }')
    ours_us=$(ours "$ours_name")
    printf 'round %d %-6s RVO2 %.3f s = %.1f us/step, ours %s us/step: %.2fx\n' "$r" "$example" \
      "$s" "$theirs_us" "$ours_us" "$(awk -v a="$theirs_us" -v b="$ours_us" 'BEGIN { print a / b }')"
  done
done
