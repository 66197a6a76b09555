#!/usr/bin/env python3
"""Measures of the code's structure, for comparing two commits (issue 44's before/after).

  scripts/structure_measures.py [--rev REV] [--commits RANGE]

Prints: README lines, the largest flat source folder, SDK sources that include a host header,
mean words per comment block in the harness, and the mean subject length of RANGE's commits.
Reads the tree of REV (default HEAD) with git, so any commit can be measured from any checkout.
"""
import argparse
import collections
import re
import subprocess
import sys


def git(*args):
    return subprocess.run(["git", *args], check=True, capture_output=True, text=True).stdout


def files_at(rev):
    return git("ls-tree", "-r", "--name-only", rev).splitlines()


def show(rev, path):
    return git("show", f"{rev}:{path}")


def comment_blocks(text):
    """Runs of consecutive // comment lines, as lists of words (license-free code only)."""
    blocks, current = [], []
    for line in text.splitlines():
        m = re.match(r"\s*///?<?\s?(.*)", line)
        if m and line.strip().startswith("//"):
            current.extend(m.group(1).split())
        elif current:
            blocks.append(current)
            current = []
    if current:
        blocks.append(current)
    return [b for b in blocks if b]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rev", default="HEAD")
    ap.add_argument("--commits", help="a git range (or revision) whose subjects are measured, e.g. A..B")
    args = ap.parse_args()
    files = files_at(args.rev)
    sources = [f for f in files if f.endswith((".cc", ".h")) and f.startswith("harness/")]

    print(f"README.md lines: {show(args.rev, 'README.md').count(chr(10))}")
    per_folder = collections.Counter(f.rsplit("/", 1)[0] for f in sources)
    folder, count = per_folder.most_common(1)[0]
    print(f"largest harness source folder: {folder} ({count} files)")
    print("harness source folders: " + ", ".join(f"{d} {n}" for d, n in sorted(per_folder.items())))

    # SDK sources: the files that define what the installed headers declare. Before the split
    # they are named by the list; after it they are the files under harness/sdk/.
    sdk_names = ("agent_index", "agent_state", "beam_scan", "collision_world", "geometry",
                 "human_placement", "interfaces", "params", "rng", "vector_units", "version",
                 "world_file", "trainable", "data_root")
    if any(f.startswith("harness/sdk/") for f in files):
        sdk = [f for f in sources if f.startswith("harness/sdk/")]
    else:
        sdk = [f for f in sources if f.startswith("harness/src/") and
               f.rsplit("/", 1)[1].rsplit(".", 1)[0] in sdk_names]
    host_headers = {f.rsplit("/", 1)[1] for f in sources if "/bench/" in f or
                    (f.startswith("harness/src/") and f.endswith(".h") and
                     f.rsplit("/", 1)[1].rsplit(".", 1)[0] not in sdk_names)}
    crossing = []
    for f in sdk:
        for inc in re.findall(r'#include "([^"]+)"', show(args.rev, f)):
            if "crowdsim/bench/" in inc or inc.rsplit("/", 1)[-1] in host_headers:
                crossing.append(f"{f} -> {inc}")
    print(f"SDK sources including a host header: {len(crossing)}")
    for c in crossing:
        print(f"  {c}")
    # DataRoot() and Trainable's destructor defined outside the SDK's sources.
    for what, pattern in (("DataRoot()", r"^fs::path DataRoot\(\)|^std::filesystem::path DataRoot\(\)"),
                          ("Trainable::~Trainable", r"Trainable::~Trainable")):
        where = [f for f in sources if f.endswith(".cc") and
                 re.search(pattern, show(args.rev, f), re.M)]
        print(f"{what} defined in: {', '.join(where) or 'nowhere'}")

    words = []
    past = 0
    for f in sources:
        if f.startswith(("harness/src/", "harness/host/", "harness/sdk/", "harness/common/")):
            text = show(args.rev, f)
            words += [len(b) for b in comment_blocks(text)]
            past += len(re.findall(r"//.*\b(had|was|were|used to|no longer)\b", text))
    print(f"harness core comment blocks: {len(words)}, mean {sum(words) / len(words):.1f} words; "
          f"comment lines with past-tense narration markers: {past}")

    if args.commits:
        subjects = git("log", "--format=%s", args.commits).splitlines()
        if subjects:
            lengths = [len(s) for s in subjects]
            over = sum(n > 72 for n in lengths)
            print(f"commits {args.commits}: {len(subjects)}, subject mean {sum(lengths) / len(lengths):.0f} "
                  f"characters, {over} over 72")
    return 0


if __name__ == "__main__":
    sys.exit(main())
