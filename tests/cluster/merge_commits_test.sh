#!/usr/bin/env bash
# `merge` joins only shards made by one commit (their manifests' git_commit) and records it in
# the merged manifest; --allow-mixed-commits joins shards of different commits and records each.
#   tests/cluster/merge_commits_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
source "$(dirname "$0")/../support/cli_test.sh" "$@"
cd "$source"
# The manifest read as JSON (python3 is a dependency): a field, a list joined by commas, a change.
field() { python3 -c 'import json, sys; print(json.load(open(sys.argv[1])).get(sys.argv[2], ""))' "$1/manifest.json" "$2"; }
list() { python3 -c 'import json, sys; print(",".join(json.load(open(sys.argv[1])).get(sys.argv[2], [])))' "$1/manifest.json" "$2"; }
set_field() {
  python3 -c 'import json, sys; m = json.load(open(sys.argv[1])); m[sys.argv[2]] = sys.argv[3]; json.dump(m, open(sys.argv[1], "w"), indent=2)' \
    "$1/manifest.json" "$2" "$3"
}

for k in 1 2; do
  "$bin" run suites/quick.yaml --episodes 10 --jobs 1 --quiet --shard "$k/2" --out "$work/s$k" \
    > "$work/s$k.log" 2>&1 || { cat "$work/s$k.log"; fail "shard $k/2"; }
done
commit=$(field "$work/s1" git_commit)
[[ -n $commit && $(field "$work/s2" git_commit) == "$commit" ]] || fail "the shards name no or two commits"

# One commit: merged, and the manifest says which commit made the shards.
"$bin" merge "$work/s1" "$work/s2" --out "$work/merged" > "$work/merge.log" 2>&1 ||
  { cat "$work/merge.log"; fail "merge of one commit's shards"; }
[[ $(field "$work/merged" shards_git_commit) == "$commit" ]] || fail "merged manifest: shards_git_commit is not $commit"
[[ $(list "$work/merged" shard_commits) == "$commit 1/2,$commit 2/2" ]] ||
  fail "merged manifest: no shard_commits for 1/2 and 2/2"

# Another commit in shard 2: refused, naming both commits and both folders; nothing written.
other=0123456789ab
set_field "$work/s2" git_commit "$other"
[[ $(field "$work/s2" git_commit) == "$other" ]] || fail "could not change the commit of shard 2"
status=0
"$bin" merge "$work/s1" "$work/s2" --out "$work/mixed" > "$work/mixed.log" 2>&1 || status=$?
# Exit 2: refused before anything was merged (1 is for a failure while running).
[[ $status -eq 2 ]] || { cat "$work/mixed.log"; fail "merge of two commits' shards exited $status, not 2"; }
for word in "$commit" "$other" "$work/s1" "$work/s2" --allow-mixed-commits; do
  grep -qF -- "$word" "$work/mixed.log" || { cat "$work/mixed.log"; fail "the error does not name $word"; }
done
[[ ! -e "$work/mixed" ]] || fail "a refused merge wrote $work/mixed"

# --allow-mixed-commits: merged, the same results, each shard's commit recorded.
"$bin" merge "$work/s1" "$work/s2" --out "$work/mixed" --allow-mixed-commits > "$work/mixed.log" 2>&1 ||
  { cat "$work/mixed.log"; fail "merge --allow-mixed-commits"; }
[[ $(field "$work/mixed" shards_git_commit) == mixed ]] || fail "shards_git_commit is not 'mixed'"
[[ $(list "$work/mixed" shard_commits) == "$commit 1/2,$other 2/2" ]] ||
  fail "merged manifest: shard_commits does not name both commits"
for f in table.md table.csv episodes.csv; do
  cmp "$work/merged/$f" "$work/mixed/$f" || fail "$f differs between the two merges of the same episodes"
done

# The option is documented in the command's help (and so completed).
"$bin" help merge | grep -qF -- --allow-mixed-commits || fail "help merge does not name --allow-mixed-commits"
"$bin" completion bash | grep -q '^ *merge).*--allow-mixed-commits' || fail "completion lacks --allow-mixed-commits"
echo "merge refuses shards of two commits unless --allow-mixed-commits, and records them: ok"
