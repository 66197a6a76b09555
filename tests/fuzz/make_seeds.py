#!/usr/bin/python3
"""Seeds for the fuzz corpus (scripts/fuzz.sh --reseed): the project's own files, one folder per
target. Suites and training files are taken as they are; world files and world sets are cut to
a few items per list (and a few mask rows, with the height to match), since the committed ones
are 30-120 KB each and libFuzzer works best on inputs of a few KB.

Usage: make_seeds.py SOURCE_DIR OUT_DIR  (writes OUT_DIR/{suite_reader,training_reader,world_reader})
"""
import pathlib
import sys

import yaml


def trim_world(world):
    for key in ("rectangles", "free_points"):
        if isinstance(world.get(key), list):
            world[key] = world[key][:6]
    pairs = world.get("robot_pairs")
    if isinstance(pairs, dict):
        for split in pairs:
            pairs[split] = pairs[split][:3]
    mask = world.get("mask")
    if isinstance(mask, dict) and isinstance(mask.get("rows"), list):
        mask["rows"] = mask["rows"][:4]
        mask["height"] = len(mask["rows"])
    if isinstance(world.get("stats"), dict):
        world["stats"] = dict(list(world["stats"].items())[:3])
    return world


def main():
    src, out = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    folders = {name: out / name for name in ("suite_reader", "training_reader", "world_reader")}
    for folder in folders.values():
        folder.mkdir(parents=True, exist_ok=True)
    for f in sorted((src / "suites").glob("*.yaml")):
        (folders["suite_reader"] / f.name).write_bytes(f.read_bytes())
    for f in sorted((src / "suites" / "train").rglob("*.yaml")):
        (folders["training_reader"] / f.name).write_bytes(f.read_bytes())
    for f in sorted((src / "worlds").rglob("*.yaml")):
        doc = yaml.safe_load(f.read_text())
        if isinstance(doc.get("worlds"), list):
            doc["worlds"] = [trim_world(w) for w in doc["worlds"][:2]]
        else:
            trim_world(doc)
        name = str(f.relative_to(src / "worlds")).replace("/", "_")
        (folders["world_reader"] / name).write_text(yaml.safe_dump(doc, sort_keys=False, width=200, default_flow_style=None))


if __name__ == "__main__":
    main()
