#!/usr/bin/env bash
# make fuzz-coverage: clang source-based coverage of src/ by the API fuzzer's
# corpus (issue 23 item 12). Builds build/fuzz-cov/fuzz_api with
# -fprofile-instr-generate -fcoverage-mapping (libFuzzer, no sanitizers), runs
# every input of fuzz/corpus/api once, and writes results/FUZZ_COVERAGE.md:
# line coverage of each src/ file and in total, and the public functions of
# include/tumble.h that the corpus never calls (regions covered: 0).
# Usage: tools/fuzz_coverage.sh "EXTRA CFLAGS" (the known-bug switches of mk/fuzz.mk)
set -euo pipefail
cd "$(dirname "$0")/.."
extra=${1:-}
dir=build/fuzz-cov
out=results/FUZZ_COVERAGE.md
mkdir -p "$dir" results
# shellcheck disable=SC2086
clang -std=c17 -O1 -g -Iinclude -Ifuzz -fsanitize=fuzzer -fprofile-instr-generate -fcoverage-mapping $extra \
  -o "$dir/fuzz_api" fuzz/fuzz_api.c src/*.c -lm
rm -f "$dir"/*.profraw
LLVM_PROFILE_FILE="$dir/api.profraw" "$dir/fuzz_api" -runs=0 fuzz/corpus/api >"$dir/run.log" 2>&1 ||
  { tail -n 20 "$dir/run.log"; exit 1; }
llvm-profdata merge -sparse "$dir/api.profraw" -o "$dir/api.profdata"
llvm-cov report "$dir/fuzz_api" -instr-profile="$dir/api.profdata" src/*.c >"$dir/files.txt"
llvm-cov report -show-functions "$dir/fuzz_api" -instr-profile="$dir/api.profdata" src/*.c include/tumble.h \
  >"$dir/functions.txt"

public=$(grep -E '^[a-z_][a-z0-9_ ]*[ *]tb_[a-z0-9_]+\(' include/tumble.h | grep -v '^typedef' |
  sed -E 's/^.*[ *](tb_[a-z0-9_]+)\(.*$/\1/' | sort -u)
# the functions with a covered region (rows "[file.c:]name regions miss cover% ..."; the
# header's inline functions have one row per file that includes it)
awk '$4 ~ /%$/ && $4 != "0.00%" { name = $1; sub(/^.*:/, "", name); print name }' "$dir/functions.txt" |
  sort -u >"$dir/called.txt"
never=()
for n in $public; do
  grep -qx "$n" "$dir/called.txt" || never+=("$n")
done
inputs=$(find fuzz/corpus/api -type f | wc -l)
{
  echo "# Coverage of src/ by the API fuzzer's corpus"
  echo
  echo "\`make fuzz-coverage\` (tools/fuzz_coverage.sh): \`fuzz/fuzz_api.c\` built with clang"
  echo "\`-fprofile-instr-generate -fcoverage-mapping\`, every input of \`fuzz/corpus/api\` ($inputs files)"
  echo "run once, \`llvm-profdata\` / \`llvm-cov report\` over \`src/\`. Commit $(git rev-parse --short HEAD)."
  echo
  echo "| file | lines | missed | line coverage | functions | missed |"
  echo "| --- | ---: | ---: | ---: | ---: | ---: |"
  awk '$1 ~ /\.c$|^TOTAL$/ && NF >= 13 {
    name = $1; sub(/^.*\//, "", name); if (name == "TOTAL") name = "**total**";
    printf "| %s | %s | %s | %s | %s | %s |\n", name, $8, $9, $10, $5, $6 }' "$dir/files.txt"
  echo
  echo "Public functions of \`include/tumble.h\`: $(echo "$public" | wc -w); never called by the corpus: ${#never[@]}."
  for n in "${never[@]+"${never[@]}"}"; do echo "- \`$n\`"; done
  echo
  echo "Named nowhere in \`fuzz/fuzz_api.c\` (\`fuzz/api_coverage.sh\`): $(fuzz/api_coverage.sh | wc -l)."
} >"$out"
cat "$out"
