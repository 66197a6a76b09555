#!/usr/bin/env python3
"""Converts CrowdNav episodes to crowdsim-bench episode logs (docs/episode_log.md), so that
`crowdsim-bench score` measures them with the social navigation metrics of a crowdsim-bench run.

CrowdNav (github.com/vita-epfl/CrowdNav) keeps an episode's states in `env.states`: per step, the
robot's FullState (px, py, vx, vy, radius, gx, gy, v_pref, theta) and the humans' ObservableStates
(px, py, vx, vy, radius). Dump them after `env.step` returns `done`, e.g. in crowd_nav/test.py:

    import json
    json.dump({"time_step": env.time_step, "kinematics": env.robot.kinematics,
               "outcome": str(info),   # ReachGoal, Collision, Timeout
               "states": [{"robot": [r.px, r.py, r.vx, r.vy, r.radius, r.gx, r.gy, r.theta],
                           "humans": [[h.px, h.py, h.vx, h.vy, h.radius] for h in hs]}
                          for r, hs in env.states]}, open("episode_0.json", "w"))

then convert and score:

    /usr/bin/python3 examples/crowdnav_to_episode_log.py episode_0.json --out logs/episode_0.jsonl.gz
    crowdsim-bench score logs

CrowdNav's worlds have no obstacles: the map is a box 5 m beyond every position logged.
CrowdNav records the state before each step; its first state is time 0.
"""
import argparse
import gzip
import json
import sys

OUTCOMES = {"Reaching goal": "success", "ReachGoal": "success", "Collision": "collision_human",
            "Timeout": "timeout"}


def convert(episode: dict) -> list:
    states = episode["states"]
    if not states:
        raise ValueError("the episode has no states")
    outcome = OUTCOMES.get(episode.get("outcome", ""))
    if outcome is None:
        raise ValueError(f"unknown outcome {episode.get('outcome')!r}: expected one of {sorted(OUTCOMES)}")
    xs = [s["robot"][0] for s in states] + [h[0] for s in states for h in s["humans"]]
    ys = [s["robot"][1] for s in states] + [h[1] for s in states for h in s["humans"]]
    bounds = [min(xs) - 5, min(ys) - 5, max(xs) + 5, max(ys) + 5]
    dt = float(episode["time_step"])
    lines = [{"format": "crowdsim-episode-log", "version": 1,
              "units": {"length": "m", "time": "s", "angle": "rad"},
              "source": "CrowdNav, converted by examples/crowdnav_to_episode_log.py", "dt": dt,
              "robot": {"holonomic": episode.get("kinematics", "holonomic") == "holonomic",
                        "goal_radius": float(episode.get("goal_radius", 0.0))},
              "map": {"bounds": bounds, "rectangles": []}}]
    for k, s in enumerate(states):
        px, py, vx, vy, radius, gx, gy, theta = s["robot"]
        lines.append({"t": k * dt,
                      "robot": {"x": px, "y": py, "vx": vx, "vy": vy, "heading": theta,
                                "radius": radius, "goal": [gx, gy]},
                      "people": [{"id": i, "x": h[0], "y": h[1], "vx": h[2], "vy": h[3], "radius": h[4]}
                                 for i, h in enumerate(s["humans"])]})
    lines.append({"outcome": outcome})
    return lines


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("episode", help="a CrowdNav episode dumped as JSON (see above)")
    parser.add_argument("--out", required=True, help="the episode log to write (.jsonl.gz)")
    args = parser.parse_args()
    try:
        with open(args.episode) as f:
            lines = convert(json.load(f))
    except (OSError, ValueError, KeyError, TypeError) as e:
        print(f"crowdnav_to_episode_log: {args.episode}: {e}", file=sys.stderr)
        return 1
    with gzip.open(args.out, "wt") as f:
        for line in lines:
            f.write(json.dumps(line) + "\n")
    print(f"wrote {args.out} ({len(lines) - 2} states)", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
