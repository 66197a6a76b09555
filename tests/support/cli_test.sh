# Sourced by the shell tests of the CLI (tests/cluster, tests/mpi) after their `set -euo
# pipefail`: build and source from the arguments, a scratch folder removed at exit, fail(),
# the CLI as $bin, and for tests started with MPIEXEC the mpirun flags in $mpi_flags.
#   source "$(dirname "$0")/../support/cli_test.sh" "$@"    (BUILD_DIR SOURCE_DIR [MPIEXEC])
build="$1"; source="$2"; mpiexec="${3:-}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
bin="$build/bin/crowdsim-bench"
mpi_flags=(--oversubscribe)
[[ $(id -u) -eq 0 ]] && mpi_flags+=(--allow-run-as-root)
true
