#!/usr/bin/env bash
# Regenerates the figures of docs/gallery.md and the README's docs/episode.png from the committed
# results (each episode is replayed from its suite, so the figures follow the code):
#
#   scripts/make_gallery.sh [--bin PATH] [--out DIR]
#
# One figure per kind the gallery promises: success, human collision, obstacle collision, timeout,
# floor plan, lidar and person readings, two policies in one episode, PPO at a floor plan's wall.
# The episode of each is the first of its row with that outcome in results/<suite>/episodes.csv.
set -euo pipefail

bin="build/bin/crowdsim-bench"
out="docs"
while [[ $# -gt 0 ]]; do
  case "$1" in
    --bin) bin="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    -h|--help) sed -n '2,9p' "$0"; exit 0 ;;
    *) echo "make_gallery: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
[[ -x "$bin" ]] || { echo "make_gallery: '$bin' not found; run 'make build' first (or pass --bin)" >&2; exit 2; }
mkdir -p "$out/gallery"

# first_episode SUITE ROW STATUS: the first episode of ROW with STATUS in the committed results.
first_episode() {
  local csv="results/$1/episodes.csv"
  [[ -f "$csv" ]] || { echo "make_gallery: no $csv (committed results missing)" >&2; exit 1; }
  local e
  e=$(awk -F, -v row="$2" -v st="$3" '$1 == row && $5 == st { print $2; exit }' "$csv")
  [[ -n "$e" ]] || { echo "make_gallery: no '$3' episode of row '$2' in $csv" >&2; exit 1; }
  echo "$e"
}

# first_pair SUITE A B STATUS_A STATUS_B [MIN_TIME_B]: the first episode where row A ends with
# STATUS_A and row B with STATUS_B, B not before MIN_TIME_B s (-1: none).
first_pair() {
  awk -F, -v a="$2" -v b="$3" -v sa="$4" -v sb="$5" -v tb="${6:-0}" '
    $1 == a { sta[$2] = $5 } $1 == b { stb[$2] = $5; timeb[$2] = $6 }
    END { best = -1
          for (e in sta) if (sta[e] == sa && stb[e] == sb && timeb[e] + 0 >= tb && (best < 0 || e + 0 < best)) best = e + 0
          print best }' "results/$1/episodes.csv"
}

render() {  # NAME ARGS...: one figure, its command line kept for the gallery page
  local name="$1"; shift
  "$bin" render "$@" --scale 1 --out "$out/gallery/$name.png" 2>&1 | sed 's/^/  /'
}

t1=suites/table1.yaml
s=$(first_episode table1 line16_sarl_pp_lidar_person_rect1 success)
render success "$t1" --row line16_sarl_pp_lidar_person_rect1 --episode "$s"
render lidar "$t1" --row line16_sarl_pp_lidar_person_rect1 --episode "$s" --sensors-at 12
e=$(first_episode table1 line17_sarl_pp_lidar_person_rect3 collision_human)
render collision_human "$t1" --row line17_sarl_pp_lidar_person_rect3 --episode "$e"
e=$(first_episode table1 line11_cadrl_pp_lidar_person_rect3 collision_obstacle)
render collision_obstacle "$t1" --row line11_cadrl_pp_lidar_person_rect3 --episode "$e"
e=$(first_episode table1 line10_cadrl_pp_lidar_person_rect1 timeout)
render timeout "$t1" --row line10_cadrl_pp_lidar_person_rect1 --episode "$e"
e=$(first_pair table1 line16_sarl_pp_lidar_person_rect1 line11_cadrl_pp_lidar_person_rect3 success collision_obstacle)
[[ "$e" -ge 0 ]] || { echo "make_gallery: no episode where line 16 succeeds and line 11 hits an obstacle" >&2; exit 1; }
render compare "$t1" --row line16_sarl_pp_lidar_person_rect1 --compare line11_cadrl_pp_lidar_person_rect3 --episode "$e"
e=$(first_episode gibson_baselines ompl_planner_hard success)
render floorplan suites/gibson_baselines.yaml --row ompl_planner_hard --episode "$e"

# PPO beside the route follower on the hard plan: the first trip where PPO hits a wall and the
# follower arrives, with PPO's readings two steps before the collision.
e=$(first_pair ppo_floorplans ppo_hard_route_s1 hard_route_follower collision_obstacle success)
[[ "$e" -ge 0 ]] || { echo "make_gallery: no ppo_floorplans trip where PPO hits a wall and the follower arrives" >&2; exit 1; }
k=$(awk -F, -v e="$e" '$1 == "ppo_hard_route_s1" && $2 == e { print ($7 > 2 ? $7 - 2 : 0); exit }' \
  results/ppo_floorplans/episodes.csv)
render ppo_wall suites/ppo_floorplans.yaml --row ppo_hard_route_s1 --compare hard_route_follower \
  --episode "$e" --sensors-at "$k"

# The named interaction scenarios (suites/social.yaml): episode 0 of the OMPL planner's row of
# each, rows 25-32 in the scenarios' order.
row=25
for scenario in frontal_approach overtaking crossing doorway narrow_hallway blind_corner \
    intersection standing_person; do
  render "scenario_$scenario" suites/social.yaml --row "$row" --episode 0
  row=$((row + 1))
done
# The group scenarios (suites/social_groups.yaml): the OMPL planner's rows 7 and 8.
render scenario_join_group suites/social_groups.yaml --row 7 --episode 0
render scenario_leave_group suites/social_groups.yaml --row 8 --episode 0

# The README's picture: ORCA and the straight-line robot in one quick.yaml episode.
e=$(first_pair quick orca linear success collision_obstacle 3)
[[ "$e" -ge 0 ]] || { echo "make_gallery: no quick.yaml episode for the README picture" >&2; exit 1; }
"$bin" render suites/quick.yaml --row orca --episode "$e" --compare linear --sensors-at 12 --scale 1.5 \
  --out "$out/episode.png" 2>&1 | sed 's/^/  /'
echo "make_gallery: figures written to $out/gallery/ and $out/episode.png"
