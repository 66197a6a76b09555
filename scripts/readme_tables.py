#!/usr/bin/env python3
"""Writes the paper-table blocks of README.md and docs/*.md from the committed results, so the
pages cannot drift from results/<suite>/table.csv: each block between `<!-- table:NAME begin -->`
and `<!-- table:NAME end -->` is the suite NAME's rows, ours (success with its 95% interval)
beside the paper's values where the row has them. A block `table:NAME:compact` has only the
rows' description, the success and the paper's success; `table:NAME:social` the description,
the success and the social navigation metrics of SOCIAL; `table:NAME:scenarios` a model x
interaction scenario matrix of success / SPL (rows swept over `social_scenarios` worlds). Every
suite of REQUIRED has a full block on some page.

    scripts/readme_tables.py            # rewrite the pages' blocks
    scripts/readme_tables.py --check    # exit 1 (and say which) when a block is out of date or missing
"""
import csv
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
BLOCK = re.compile(r"(<!-- table:(?P<name>[\w.-]+)(?P<form>(?::compact|:social|:scenarios)?) begin -->\n)(?P<body>.*?)"
                   r"(<!-- table:(?P=name)(?P=form) end -->)", re.S)
# The pages that hold blocks, and the suites whose full table one of them must hold.
PAGES = [ROOT / "README.md"] + sorted((ROOT / "docs").glob("*.md"))
REQUIRED = ["table1", "table1_3obs", "table2", "table1_route", "table2_route", "human_models",
            "kinematics", "perception", "people", "ppo", "ppo_floorplans"]
# The social navigation metrics a `:social` block shows (table.csv headers, docs/metrics.md).
SOCIAL = ["SPL", "accel. mean", "jerk mean", "path irregularity", "freezing time", "personal share",
          "personal intrusions", "min. TTC"]
INFO = ["line", "model", "humans.policy", "kinematics", "perception", "sensor(s)", "# of obstacles", "humans", "floor plan", "seed",
        "weights", "procedure"]
# The paper's column names where they need a word more out of the paper's context.
HEADER = {"# of obstacles": "trained with # obstacles", "humans": "trained with humans",
          "humans.policy": "people", "kinematics": "robot body"}
# Where a suite's info column means something else: the people suite sweeps its test people.
SUITE_HEADER = {"people": {"humans": "people (humans: ...)"}}


def rate(row, key):
    return f"{float(row[key]):.3f}"


def paper(row, key):
    value = row.get(f"paper {key}", "")
    return f"{float(value):.3f}" if value else "-"


def table(name: str, compact: bool = False, social: bool = False, scenarios: bool = False) -> str:
    path = ROOT / "results" / name / "table.csv"
    if not path.is_file():
        raise SystemExit(f"readme_tables: {path} does not exist (run the suite {name} first)")
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    info = [c for c in INFO if rows and c in rows[0]]
    with_paper = any(r.get("paper success") for r in rows)
    headers = {**HEADER, **SUITE_HEADER.get(name, {})}
    if compact:
        return compact_table(rows, [c for c in info if c not in ("weights", "procedure")], with_paper)
    if social:
        return social_table(rows, info)
    if scenarios:
        return scenario_matrix(rows)
    head = info + ["success [95% CI]"] + (["paper"] if with_paper else []) + \
        ["collision"] + (["paper"] if with_paper else []) + ["timeout"] + \
        (["paper"] if with_paper else []) + ["nav. time"] + (["paper"] if with_paper else [])
    lines = header_lines(head, info, headers)
    for r in rows:
        cells = [r[c] for c in info] + [success_cell(r)]
        for ours, theirs in (("success rate", "success"), ("collision rate", "collision"),
                             ("timeout rate", "timeout"), ("nav. time", "nav. time")):
            if ours != "success rate":
                cells.append(f"{float(r[ours]):.2f}" if ours == "nav. time" else rate(r, ours))
            if with_paper:
                value = paper(r, theirs)
                cells.append(value if theirs != "nav. time" or value == "-" else f"{float(value):.2f}")
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def header_lines(head, info, headers=HEADER):
    """A Markdown table's header and alignment rows: info columns left, figures right."""
    return ["| " + " | ".join(headers.get(c, c) for c in head) + " |",
            "|" + "|".join("---" if c in info else "---:" for c in head) + "|"]


def success_cell(r) -> str:
    """The success rate with its 95% interval."""
    return (f"{rate(r, 'success rate')} [{float(r['success 95% low']):.3f}, "
            f"{float(r['success 95% high']):.3f}]")


def compact_table(rows, info, with_paper: bool) -> str:
    head = info + ["success [95% CI]"] + (["paper"] if with_paper else [])
    lines = header_lines(head, info)
    for r in rows:
        cells = [r[c] for c in info] + [success_cell(r)]
        if with_paper:
            cells.append(paper(r, "success"))
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def social_table(rows, info) -> str:
    missing = [c for c in SOCIAL if rows and c not in rows[0]]
    if missing:
        raise SystemExit("readme_tables: a :social block's suite has no column " + ", ".join(missing) +
                         " (name a social metric in its columns:)")
    head = info + ["success [95% CI]"] + SOCIAL
    lines = header_lines(head, info)
    for r in rows:
        lines.append("| " + " | ".join([r[c] for c in info] + [success_cell(r)] +
                                       [r[c] for c in SOCIAL]) + " |")
    return "\n".join(lines) + "\n"


SCENARIO = re.compile(r"scenario: (?P<name>\w+)")


def scenario_matrix(rows) -> str:
    """Models down, scenarios across, each cell the success rate / SPL (/ group intrusions, the
    mean per episode, when the suite has them)."""
    groups = bool(rows) and "group intrusions" in rows[0]
    models, scenarios, cells = [], [], {}
    for r in rows:
        m = SCENARIO.search(r["label"])
        if not m:
            raise SystemExit(f"readme_tables: row {r['label']!r} names no social_scenarios scenario")
        model, scenario = r["model"], m.group("name")
        if model not in models:
            models.append(model)
        if scenario not in scenarios:
            scenarios.append(scenario)
        cells[model, scenario] = f"{rate(r, 'success rate')} / {float(r['SPL']):.2f}"
        if groups:
            cells[model, scenario] += f" / {float(r['group intrusions']):.2f}"
    head = ["model"] + [s.replace("_", " ") for s in scenarios]
    lines = ["| " + " | ".join(head) + " |", "|---|" + "---:|" * len(scenarios)]
    for model in models:
        lines.append("| " + " | ".join([model] + [cells.get((model, s), "-") for s in scenarios]) + " |")
    return "\n".join(lines) + "\n"


def main() -> int:
    check = "--check" in sys.argv[1:]
    stale = []
    full = set()
    for page in PAGES:
        text = page.read_text()
        name = page.relative_to(ROOT).as_posix()

        def fill(m):
            compact = m.group("form") == ":compact"
            social = m.group("form") == ":social"
            scenarios = m.group("form") == ":scenarios"
            if not compact and not social and not scenarios:
                full.add(m.group("name"))
            body = table(m.group("name"), compact, social, scenarios)
            if body != m.group("body"):
                stale.append(f"{name}: {m.group('name')}{m.group('form')}")
            return m.group(1) + body + m.group(5)

        new = BLOCK.sub(fill, text)
        if not check and new != text:
            page.write_text(new)
    missing = [s for s in REQUIRED if s not in full]
    if missing:
        print("readme_tables: no page has a table block for " + ", ".join(missing) +
              " (<!-- table:NAME begin --> ... <!-- table:NAME end -->)")
        return 1
    if check:
        if stale:
            print("readme_tables: tables out of date: " + "; ".join(stale) +
                  ": run scripts/readme_tables.py")
            return 1
        print(f"readme_tables: the tables of {len(PAGES)} pages match results/")
        return 0
    print("readme_tables: " + ("; ".join(stale) + " rewritten" if stale else "nothing to change"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
