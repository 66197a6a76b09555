#!/usr/bin/python3
"""Seeds for the fuzz corpus (scripts/fuzz.sh --reseed): the project's own files, one folder per
target. Suites and training files are taken as they are; world files and world sets are cut to
a few items per list (and a few mask rows, with the height to match), since the committed ones
are 30-120 KB each and libFuzzer works best on inputs of a few KB.

The run's files come from the committed results: episodes.csv cut to its first lines (and
variants with the damage a resume must set aside), manifest.json as it is. Plugin files are
made here: ELF headers whose offsets and counts point past a short file, as an interrupted copy
leaves them.

Usage: make_seeds.py SOURCE_DIR OUT_DIR  (writes OUT_DIR/<target> for every target)
"""
import json
import pathlib
import struct
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


def trim_json(value):
    """The same shape with at most two items per list: a few KB."""
    if isinstance(value, list):
        return [trim_json(v) for v in value[:2]]
    if isinstance(value, dict):
        items = list(value.items())
        return {k: trim_json(v) if isinstance(v, (list, dict)) else v for k, v in items}
    return value


def episodes_seeds(src):
    """(name, bytes) pairs: the first lines of each committed episodes.csv, and damaged copies."""
    seeds = []
    for f in sorted((src / "results").glob("*/episodes.csv")):
        lines = f.read_text().splitlines(keepends=True)[:12]
        seeds.append((f.parent.name + ".csv", "".join(lines)))
    header, first = seeds[0][1].splitlines(keepends=True)[:2]
    fields = first.rstrip("\n").split(",")
    for name, index, value in (("nan_time", 5, "nan"), ("negative_steps", 6, "-5"),
                               ("inf_path", 8, "-inf"), ("huge_episode", 1, "99999999999")):
        damaged = list(fields)
        damaged[index] = value
        seeds.append((name + ".csv", header + first + ",".join(damaged) + "\n"))
    seeds.append(("cut_last_line.csv", header + first + first[: len(first) // 2]))
    seeds.append(("conflicting_duplicate.csv",
                  header + first + first.replace(",success,", ",timeout,")))
    seeds.append(("header_only.csv", header))
    return seeds


def elf_seeds():
    """(name, bytes) pairs: 64-bit ELF shared-object headers pointing past a short file."""
    def header(phoff, phnum, shoff, shnum, e_type=3, machine=62):
        ident = b"\x7fELF" + bytes([2, 1, 1, 0]) + bytes(8)
        return ident + struct.pack("<HHIQQQIHHHHHH", e_type, machine, 1, 0, phoff, shoff, 0,
                                   64, 56, phnum, 64, shnum, 0)
    load = struct.pack("<IIQQQQQQ", 1, 5, 0, 0, 0, 0x4000, 0x4000, 0x1000)
    return [
        ("header_only.so", header(64, 1, 0, 0)),
        ("segment_past_end.so", header(64, 1, 0, 0) + load),
        ("sections_past_end.so", header(64, 1, 1 << 20, 30) + load),
        ("many_segments.so", header(64, 0xFFFF, 0, 0) + load),
        ("executable_not_shared.so", header(64, 1, 0, 0, e_type=2) + load),
        ("other_machine.so", header(64, 1, 0, 0, machine=183) + load),
        ("32_bit.so", b"\x7fELF" + bytes([1, 1, 1, 0]) + bytes(44)),
        ("short.so", b"\x7fELF"),
        ("text.so", b"this is text, not a shared library\n"),
        ("phoff_overflow.so", header(0xFFFFFFFFFFFFFFF0, 2, 0, 0) + load),
    ]


def main():
    src, out = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    folders = {name: out / name for name in ("suite_reader", "training_reader", "world_reader",
                                             "episodes_reader", "manifest_reader", "plugin_file")}
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
    for name, text in episodes_seeds(src):
        (folders["episodes_reader"] / name).write_text(text)
    for f in sorted((src / "results").glob("*/manifest.json")):
        text = json.dumps(trim_json(json.loads(f.read_text())), indent=1) + "\n"
        (folders["manifest_reader"] / (f.parent.name + ".json")).write_text(text)
    (folders["manifest_reader"] / "cut.json").write_bytes(
        (src / "results" / "quick" / "manifest.json").read_bytes()[:300])
    for name, data in elf_seeds():
        (folders["plugin_file"] / name).write_bytes(data)


if __name__ == "__main__":
    main()
