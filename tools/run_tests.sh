#!/usr/bin/env bash
# Runs each check suite binary given, prints its summary, and a total at the end.
# Exits non-zero when any suite fails.
set -u
failed=()
for t in "$@"; do
  echo "== $t"
  if ! "$t"; then failed+=("$t"); fi
done
echo "== $# suites run, ${#failed[@]} failed"
if [ ${#failed[@]} -gt 0 ]; then
  printf '   failed: %s\n' "${failed[@]}"
  exit 1
fi
