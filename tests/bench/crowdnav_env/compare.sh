#!/usr/bin/env bash
# CrowdNav's env against ours on CrowdNav's task (issue 14: whole episodes, >= 150x). Needs a
# checkout of CrowdNav (github.com/vita-epfl/CrowdNav) and of RVO2's C++ library
# (github.com/snape/RVO2), which Python-RVO2 wraps; neither is part of this repository.
# Python-RVO2 and gym are not packaged by Debian: rvo2_module.cc wraps RVO2 for Python with
# pybind11 (the calls CrowdNav makes, Python-RVO2's argument order), and stubs/ stands in for
# the two gym names and the matplotlib modules CrowdNav imports at the top (render() only).
# Each round also runs rvo2_task.cc, RVO2's C++ alone on the same six agents, for scale.
#
#   tests/bench/crowdnav_env/compare.sh CROWDNAV_DIR RVO2_DIR [EPISODES] [ROUNDS]
# Run from the repository root after a Release build (build/bench/crowdnav_episode_bench).
set -euo pipefail
crowdnav="$(cd "${1:?usage: compare.sh CROWDNAV_DIR RVO2_DIR [EPISODES] [ROUNDS]}" && pwd)"
rvo2="$(cd "${2:?usage: compare.sh CROWDNAV_DIR RVO2_DIR [EPISODES] [ROUNDS]}" && pwd)"
episodes="${3:-500}"
rounds="${4:-3}"
here="$(cd "$(dirname "$0")" && pwd)"
python=/usr/bin/python3
bench=build/bench/crowdnav_episode_bench
[[ -x "$bench" ]] || { echo "compare: $bench not built (make bench)" >&2; exit 2; }
module_dir="$(mktemp -d)"
trap 'rm -rf "$module_dir"' EXIT
suffix="$("$python" -c 'import sysconfig; print(sysconfig.get_config_var("EXT_SUFFIX"))')"
includes="$("$python" -c 'import sysconfig; print(sysconfig.get_paths()["include"])')"
# -O2, as RVO2's own build and the RVO2 comparison in the README.
g++ -O2 -DNDEBUG -std=c++17 -shared -fPIC "$here/rvo2_module.cc" "$rvo2"/src/*.cc \
  -I"$rvo2/src" -I"$includes" -o "$module_dir/rvo2$suffix"
# For scale: RVO2's C++ alone on the same crowd (the ORCA solve both envs do), per step.
g++ -O2 -DNDEBUG -std=c++17 "$here/rvo2_task.cc" "$rvo2"/src/*.cc -I"$rvo2/src" \
  -o "$module_dir/rvo2_task"
for ((r = 1; r <= rounds; r++)); do
  PYTHONPATH="$module_dir:$crowdnav:$here/stubs" "$python" "$here/run_crowdnav.py" "$crowdnav" "$episodes"
  "$bench" --benchmark_min_time=1 2>/dev/null | grep '^BM_'
  "$module_dir/rvo2_task"
done
