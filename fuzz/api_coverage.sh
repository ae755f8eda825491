#!/usr/bin/env bash
# Lists the functions of include/tumble.h that a harness never names (issue 23
# item 12: the API fuzzer must drive every one). Usage:
#   fuzz/api_coverage.sh [HARNESS.c]      (default fuzz/fuzz_api.c)
# Prints one name a line and exits 1 when any is missing; prints nothing and
# exits 0 when all are named. make fuzz-coverage measures what the corpus
# really calls (llvm-cov), this only what the source names.
set -euo pipefail
cd "$(dirname "$0")/.."
harness=${1:-fuzz/fuzz_api.c}
# every declaration "type name(" at the start of a line (typedefs excluded)
names=$(grep -E '^[a-z_][a-z0-9_ *]*[ *]tb_[a-z0-9_]+\(' include/tumble.h | grep -v '^typedef' |
  sed -E 's/^.*[ *](tb_[a-z0-9_]+)\(.*$/\1/' | sort -u)
missing=0
for n in $names; do
  if ! grep -qE "\\b$n\\b" "$harness"; then echo "$n"; missing=1; fi
done
exit $missing
