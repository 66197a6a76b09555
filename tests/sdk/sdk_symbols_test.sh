#!/usr/bin/env bash
# libcrowdsim_sdk.so exports the SDK and nothing else. Each symbol it defines in the dynamic
# table and that names crowdsim:: must name a type or function that an SDK header declares
# (harness/sdk/include/crowdsim/*.h), and none a host header's (harness/host/include/).
# The SDK's internals (its sources' own helpers) must stay hidden: one is checked by name.
#   tests/sdk/sdk_symbols_test.sh BUILD_DIR SOURCE_DIR
set -uo pipefail
lib="$1/lib/libcrowdsim_sdk.so"
src="$2"
fail() { echo "FAIL: $*" >&2; exit 1; }
[[ -f "$lib" ]] || fail "no $lib"
sdk_headers=("$src"/harness/sdk/include/crowdsim/*.h)
host_headers=$(find "$src/harness/host/include" -name '*.h')
# The declared names of a set of headers: identifiers after class/struct/enum, and before '('.
names_of() {
  sed -e 's|//.*||; s|CROWDSIM_SDK_API ||g' "$@" | grep -o -E '(class|struct|enum class|enum|using) +[A-Za-z_][A-Za-z0-9_]*|[A-Za-z_~][A-Za-z0-9_]* *\(' |
    sed -E 's/^(class|struct|enum class|enum|using) +//; s/ *\($//; s/^~//' | sort -u
}
sdk_names=$(names_of "${sdk_headers[@]}")
host_only=$(comm -23 <(names_of $host_headers) <(echo "$sdk_names"))
# Defined dynamic symbols, demangled; the crowdsim ones, with their first name after crowdsim::
# (a function, a type or a namespace-level variable), vtables and typeinfo included.
mapfile -t symbols < <(nm -D --defined-only -C "$lib" | awk '{$1=""; $2=""; sub(/^  /, ""); print}' | grep 'crowdsim::')
[[ ${#symbols[@]} -ge 50 ]] || fail "only ${#symbols[@]} crowdsim symbols exported; expected the SDK's (50 or more)"
status=0
for s in "${symbols[@]}"; do
  # Only crowdsim's own symbols: std:: and Eigen:: instantiations over SDK types are the
  # compiler's (vague linkage) and named by their outer template.
  base=$(sed -E 's/^(vtable for |typeinfo for |typeinfo name for |VTT for |non-virtual thunk to |guard variable for )//' <<< "$s")
  [[ "$base" == crowdsim::* ]] || continue
  # crowdsim::A::B(...) -> A (the class or function); strip template arguments first.
  first=$(sed -E 's/^crowdsim:://; s/\[abi:[a-z0-9]+\]//g; s/<.*//; s/\(.*//; s/::.*//' <<< "$base")
  if grep -qx -- "$first" <<< "$host_only"; then
    echo "host symbol exported: $s"; status=1
  elif ! grep -qx -- "$first" <<< "$sdk_names"; then
    echo "exported symbol not declared by an SDK header: $s"; status=1
  fi
done
# Internals stay hidden: the beam kernels behind CollisionWorld (sdk/src/beam_scan.h).
internal=$(nm -D --defined-only -C "$lib" | grep -c -E 'crowdsim::.*(ScanBeams|BeamScan)' || true)
[[ "$internal" -eq 0 ]] || { echo "the SDK's internal beam kernels are exported"; status=1; }
[[ $status -ne 0 ]] || echo "sdk_symbols: ${#symbols[@]} exported crowdsim symbols, each declared by an SDK header; no host symbol, no internal"
exit $status
