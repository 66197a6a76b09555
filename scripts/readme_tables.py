#!/usr/bin/env python3
"""Writes the paper-table blocks of README.md from the committed results, so the README cannot
drift from results/<suite>/table.csv: each block between `<!-- table:NAME begin -->` and
`<!-- table:NAME end -->` is the suite NAME's rows, ours (success with its 95% interval) beside
the paper's values where the row has them.

    scripts/readme_tables.py            # rewrite README.md's blocks
    scripts/readme_tables.py --check    # exit 1 (and say which) when a block is out of date
"""
import csv
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
BLOCK = re.compile(r"(<!-- table:(?P<name>[\w.-]+) begin -->\n)(?P<body>.*?)(<!-- table:(?P=name) end -->)",
                   re.S)
INFO = ["line", "model", "sensor(s)", "# of obstacles", "humans", "floor plan", "seed", "weights",
        "procedure"]
# The paper's column names where they need a word more out of the paper's context.
HEADER = {"# of obstacles": "trained with # obstacles", "humans": "trained with humans"}


def rate(row, key):
    return f"{float(row[key]):.3f}"


def paper(row, key):
    value = row.get(f"paper {key}", "")
    return f"{float(value):.3f}" if value else "-"


def table(name: str) -> str:
    path = ROOT / "results" / name / "table.csv"
    if not path.is_file():
        raise SystemExit(f"readme_tables: {path} does not exist (run the suite {name} first)")
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    info = [c for c in INFO if rows and c in rows[0]]
    with_paper = any(r.get("paper success") for r in rows)
    head = info + ["success [95% CI]"] + (["paper"] if with_paper else []) + \
        ["collision"] + (["paper"] if with_paper else []) + ["timeout"] + \
        (["paper"] if with_paper else []) + ["nav. time"] + (["paper"] if with_paper else [])
    lines = ["| " + " | ".join(HEADER.get(c, c) for c in head) + " |",
             "|" + "|".join("---" if c in info else "---:" for c in head) + "|"]
    for r in rows:
        cells = [r[c] for c in info]
        cells.append(f"{rate(r, 'success rate')} [{float(r['success 95% low']):.3f}, "
                     f"{float(r['success 95% high']):.3f}]")
        for ours, theirs in (("success rate", "success"), ("collision rate", "collision"),
                             ("timeout rate", "timeout"), ("nav. time", "nav. time")):
            if ours != "success rate":
                cells.append(f"{float(r[ours]):.2f}" if ours == "nav. time" else rate(r, ours))
            if with_paper:
                value = paper(r, theirs)
                cells.append(value if theirs != "nav. time" or value == "-" else f"{float(value):.2f}")
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def main() -> int:
    check = "--check" in sys.argv[1:]
    readme = ROOT / "README.md"
    text = readme.read_text()
    stale = []

    def fill(m):
        body = table(m.group("name"))
        if body != m.group("body"):
            stale.append(m.group("name"))
        return m.group(1) + body + m.group(4)

    new = BLOCK.sub(fill, text)
    if check:
        if stale:
            print("readme_tables: README.md's tables are out of date for " + ", ".join(stale) +
                  ": run scripts/readme_tables.py")
            return 1
        print("readme_tables: README.md's tables match results/")
        return 0
    if new != text:
        readme.write_text(new)
    print("readme_tables: " + (", ".join(stale) + " rewritten" if stale else "nothing to change"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
