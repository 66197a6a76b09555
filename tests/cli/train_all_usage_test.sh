#!/usr/bin/env bash
# scripts/train_all.sh refuses a bad command line with exit 2, a message that names the option
# or the entry, and before it installs or trains anything: an option without its value (it
# stopped with bash's "$2: unbound variable", exit 1), a -j that is not a whole number >= 1
# (-j 0 ran every training at once, xargs -P 0; -j abc failed in xargs after the frozen copy was
# made), a FILE@ with no seed (trained with the file's own seed), two files that train into one
# folder (run side by side, the second failed at the folder's lock). A stand-in program (--bin)
# records whether anything was started.
#   tests/cli/train_all_usage_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
source "$(dirname "$0")/../support/cli_test.sh" "$@"
cd "$work"
cat > fake-bench <<'SH'
#!/usr/bin/env bash
echo "$*" >> "$(dirname "$0")/started"
SH
chmod +x fake-bench
printf 'name: tiny\n' > tiny.yaml
# expect_refusal MESSAGE ARGS...: exit 2, MESSAGE on stderr, nothing started.
expect_refusal() {
  local message="$1"; shift
  local rc=0
  "$source/scripts/train_all.sh" "$@" > out.log 2>&1 || rc=$?
  [[ $rc == 2 ]] || { cat out.log; fail "train_all.sh $* exited $rc, not 2"; }
  grep -qF -- "$message" out.log || { cat out.log; fail "train_all.sh $*: no '$message'"; }
  [[ ! -e started ]] || { cat out.log; fail "train_all.sh $* started a training"; }
}
for option in -j --seeds --build --bin; do
  expect_refusal "train_all: $option needs a value" --bin "$work/fake-bench" tiny.yaml "$option"
done
expect_refusal "train_all: -j takes a whole number >= 1, got '0'" -j 0 --bin "$work/fake-bench" tiny.yaml
expect_refusal "train_all: -j takes a whole number >= 1, got 'abc'" -j abc --bin "$work/fake-bench" tiny.yaml
expect_refusal "train_all: 'tiny.yaml@' has no seed after '@'" --bin "$work/fake-bench" tiny.yaml@
# Two files of one name train into one folder: refused before the first starts.
mkdir -p other && printf 'name: tiny\n' > other/tiny.yaml
expect_refusal "train_all: 'other/tiny.yaml' trains into results/train/tiny, as 'tiny.yaml' does" \
  --bin "$work/fake-bench" tiny.yaml other/tiny.yaml
# The same command line with a value that fits starts the training (the stand-in records it).
"$source/scripts/train_all.sh" -j 1 --bin "$work/fake-bench" tiny.yaml@7 > ok.log 2>&1 ||
  { cat ok.log; fail "train_all.sh -j 1 tiny.yaml@7"; }
grep -q "train tiny.yaml --out results/train/tiny_seed7 --quiet --seed 7" started ||
  { cat ok.log started; fail "the training was not started as expected"; }
echo "train_all.sh refuses a bad command line before it starts anything: ok"
