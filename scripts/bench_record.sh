#!/usr/bin/env bash
# Runs a build's Google Benchmarks and appends their figures to this machine's results file,
# tests/bench/results/<machine>.csv (the columns: tests/bench/results/README.md).
#
#   scripts/bench_record.sh [options] [BUILD]          # BUILD defaults to build
#     --filter REGEX     only the benchmarks whose name matches (--benchmark_filter)
#     --bench NAME       only BUILD/bench/NAME (repeatable; default: every BUILD/bench/*_bench)
#     --min-time T       --benchmark_min_time (default 0.2, as make bench)
#     --repetitions N    --benchmark_repetitions; the median is recorded (default 1)
#     --machine NAME     the results file's name (default: from /proc/cpuinfo, see below)
#     --note TEXT        the note column of every row (e.g. "quiet machine")
#     --out DIR          the folder of the results file (default tests/bench/results)
#     --dry-run          print the rows instead of appending them
#
# The machine name is the processor's model name in lower case, words joined by '-', without
# "(R)", "(TM)", "CPU", "Processor" and the clock, then its family and model: "AMD EPYC",
# family 26, model 2 gives amd-epyc-26-2. CROWDSIM_BENCH_MACHINE or --machine overrides it.
set -euo pipefail

src="$(cd "$(dirname "$0")/.." && pwd)"
build=build
filter=""
min_time=0.2
repetitions=1
machine="${CROWDSIM_BENCH_MACHINE:-}"
note=""
out="$src/tests/bench/results"
dry_run=0
benches=()
usage() { sed -n '2,17p' "$0" | sed 's/^# \{0,1\}//'; }
while [[ $# -gt 0 ]]; do
  case "$1" in
    --filter) filter="$2"; shift 2 ;;
    --bench) benches+=("$2"); shift 2 ;;
    --min-time) min_time="$2"; shift 2 ;;
    --repetitions) repetitions="$2"; shift 2 ;;
    --machine) machine="$2"; shift 2 ;;
    --note) note="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --dry-run) dry_run=1; shift ;;
    -h|--help) usage; exit 0 ;;
    -*) echo "bench_record: unknown option $1" >&2; usage >&2; exit 2 ;;
    *) build="$1"; shift ;;
  esac
done
[[ -d "$build/bench" ]] || { echo "bench_record: $build/bench does not exist (build the project first)" >&2; exit 2; }
build="$(cd "$build" && pwd)"

# The machine: model name, family and model of the first processor.
if [[ -z "$machine" ]]; then
  cpu_field() { awk -F': *' -v k="$1" '$1 ~ "^"k"[ \t]*$" {print $2; exit}' /proc/cpuinfo; }
  model_name=$(cpu_field "model name")
  [[ -n "$model_name" ]] || { echo "bench_record: no model name in /proc/cpuinfo; give --machine NAME" >&2; exit 2; }
  machine=$(sed -E -e 's/\((R|TM|tm|r)\)//g' -e 's/@.*$//' -e 's/\b(CPU|Processor)\b//g' <<<"$model_name" |
            tr 'A-Z' 'a-z' | sed -E -e 's/[^a-z0-9]+/-/g' -e 's/^-+|-+$//g')
  family=$(cpu_field "cpu family")
  model=$(cpu_field "model")
  [[ -z "$family" ]] || machine="$machine-$family"
  [[ -z "$model" ]] || machine="$machine-$model"
fi
[[ "$machine" =~ ^[A-Za-z0-9._-]+$ ]] || { echo "bench_record: machine name '$machine' is not a file name" >&2; exit 2; }

# The commit the build was made from: the CLI's --version, else the source tree's HEAD.
commit=""
if [[ -x "$build/bin/crowdsim-bench" ]]; then
  commit=$("$build/bin/crowdsim-bench" --version 2>/dev/null | grep -oE '\b[0-9a-f]{7,40}(-dirty)?\b' | head -n 1 || true)
fi
if [[ -z "$commit" ]]; then
  commit=$(git -C "$src" rev-parse --short HEAD 2>/dev/null || echo unknown)
  [[ -z "$(git -C "$src" status --porcelain --untracked-files=no 2>/dev/null)" ]] || commit="$commit-dirty"
fi
date=$(date -u +%F)

if [[ ${#benches[@]} -eq 0 ]]; then
  shopt -s nullglob
  for b in "$build"/bench/*_bench; do benches+=("$(basename "$b")"); done
fi
[[ ${#benches[@]} -gt 0 ]] || { echo "bench_record: no benchmarks in $build/bench" >&2; exit 2; }

file="$out/$machine.csv"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
status=0
for name in "${benches[@]}"; do
  exe="$build/bench/$name"
  [[ -x "$exe" ]] || { echo "bench_record: $exe is not an executable" >&2; status=1; continue; }
  args=(--benchmark_format=json "--benchmark_min_time=$min_time")
  [[ -z "$filter" ]] || args+=("--benchmark_filter=$filter")
  if [[ "$repetitions" -gt 1 ]]; then
    args+=("--benchmark_repetitions=$repetitions" --benchmark_report_aggregates_only=true)
  fi
  # A filter that matches none of this file's benchmarks is no error: the file is passed over.
  if [[ -n "$filter" ]]; then
    listed=$("$exe" --benchmark_list_tests "--benchmark_filter=$filter" 2>/dev/null || true)
    [[ -n "$listed" ]] || continue
  fi
  echo "bench_record: $name ${args[*]:1}" >&2
  if ! "$exe" "${args[@]}" > "$tmp/$name.json"; then
    echo "bench_record: $name failed" >&2
    status=1
    continue
  fi
  command="build/bench/$name$(printf ' %q' "${args[@]:1}")"
  python3 - "$tmp/$name.json" "$tmp/rows.csv" "$date" "$commit" "$name" "$command" "$note" <<'EOF'
import csv, json, sys
path, rows_path, date, commit, exe, command, note = sys.argv[1:]
with open(path) as f:
    report = json.load(f)
# Keys of a Google Benchmark run that are not user counters.
standard = {"name", "family_index", "per_family_instance_index", "run_name", "run_type",
            "repetitions", "repetition_index", "threads", "iterations", "real_time", "cpu_time",
            "time_unit", "aggregate_name", "aggregate_unit", "label", "error_occurred",
            "error_message", "skipped", "skip_message"}
runs = report.get("benchmarks", [])
aggregated = any(r.get("run_type") == "aggregate" for r in runs)
with open(rows_path, "a", newline="") as f:
    out = csv.writer(f, lineterminator="\n")
    for r in runs:
        if r.get("error_occurred") or r.get("skipped"):
            continue
        if aggregated and (r.get("run_type") != "aggregate" or r.get("aggregate_name") != "median"):
            continue
        name = r.get("run_name", r["name"])
        extra = f"real_time {r['real_time']:.6g} {r['time_unit']}; "
        # An aggregate's iterations are its repetitions.
        extra += (f"median of {r.get('repetitions', '')} repetitions" if aggregated
                  else f"iterations {r.get('iterations', '')}")
        out.writerow([date, commit, f"{exe}/{name}", "cpu_time", f"{r['cpu_time']:.6g}",
                      r["time_unit"], "", "", command, "; ".join(x for x in (note, extra) if x)])
        for key, value in r.items():
            if key not in standard and isinstance(value, (int, float)):
                unit = "1/s" if key.endswith("_per_second") else ""
                out.writerow([date, commit, f"{exe}/{name}", key, f"{value:.6g}", unit, "", "",
                              command, note])
EOF
done

if [[ ! -s "$tmp/rows.csv" ]]; then
  echo "bench_record: no figures (no benchmark matched${filter:+ '$filter'})" >&2
  exit 1
fi
header="date,commit,benchmark,metric,value,unit,against,ratio,command,note"
if [[ $dry_run == 1 ]]; then
  echo "$header"
  cat "$tmp/rows.csv"
else
  mkdir -p "$out"
  [[ -s "$file" ]] || echo "$header" > "$file"
  cat "$tmp/rows.csv" >> "$file"
  echo "bench_record: $(wc -l < "$tmp/rows.csv") rows appended to $file" >&2
fi
exit $status
