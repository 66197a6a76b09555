#!/usr/bin/env bash
# Copies a finished training into results/models/<folder name>/ for committing: the weights
# (weights.pt last, best.pt best on validation, il.pt imitation start), training.yaml,
# training_log.csv (validation), training_episodes.csv.gz (every episode), the learning
# curve (SVG and PNG), summary.json and the trainer's log. Refuses an unfinished training.
#
#   scripts/collect_model.sh [--into SUBFOLDER] results/train/<name>[_seed<N>] [...]
# (--into experiments: results/models/experiments/<name>/, for models of procedure experiments)
set -euo pipefail
into=""
if [[ "${1:-}" == "--into" ]]; then into="${2:?--into needs a folder name}/"; shift 2; fi
[[ $# -gt 0 ]] || { sed -n '2,9p' "$0"; exit 2; }
for src in "$@"; do
  src="${src%/}"
  if ! grep -q '"finished": true' "$src/summary.json" 2>/dev/null; then
    echo "collect_model: '$src' is not a finished training (summary.json says so)" >&2
    exit 1
  fi
  dst="results/models/$into$(basename "$src")"
  rm -rf "$dst"
  mkdir -p "$dst"
  for f in weights.pt best.pt il.pt training.yaml training_log.csv summary.json learning_curve.svg learning_curve.png train.log; do
    [[ -f "$src/$f" ]] && cp "$src/$f" "$dst/"
  done
  gzip -9 -n -c "$src/training_episodes.csv" > "$dst/training_episodes.csv.gz"
  # The learning curve redrawn from the full logs by this build (older builds drew SVG only).
  if [[ -x build/bin/crowdsim-bench ]]; then
    for ext in svg png; do build/bin/crowdsim-bench report "$src" --out "$dst/learning_curve.$ext" 2>/dev/null; done
  fi
  echo "collect_model: $dst ($(du -sh "$dst" | cut -f1))"
done
