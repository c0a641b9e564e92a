#!/usr/bin/env bash
# Runs the libFuzzer harnesses (fuzz/*.cpp) with ASan+UBSan.
#   scripts/fuzz.sh [RUNS]      each harness for RUNS executions (default 20000: the CI smoke run)
#   FUZZ_JOBS=2 scripts/fuzz.sh 10000000
# Corpora grow in build/fuzz/corpus/<harness>, seeded from fuzz/seeds/<harness> (and CONTACT's
# examples when ../shared is present). A finding stops the run, leaves crash-*/timeout-*/leak-*
# files in build/fuzz/findings and exits non-zero; keep it as a test in tests/data/malformed*.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-20000}
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j"$(nproc)" --target fuzz_inp fuzz_toml fuzz_profiles >/dev/null
mkdir -p build/fuzz/findings
examples=../shared/reference/contact-examples
for h in inp toml profiles; do
  corpus=build/fuzz/corpus/$h
  mkdir -p "$corpus"
  cp -n fuzz/seeds/$h/* "$corpus"/ 2>/dev/null || true
  if [ "$h" = inp ] && [ -d "$examples" ]; then cp -n "$examples"/*.inp "$corpus"/ || true; fi
  echo "== fuzz_$h: $runs runs, corpus $(ls "$corpus" | wc -l) files"
  # -rss_limit_mb: the readers allow 2 000 000 elements; -timeout: a case must not take seconds;
  # -max_len 4096: large inputs add little coverage and cut the rate tenfold (ASan).
  build/fuzz/fuzz/fuzz_$h "$corpus" -runs="$runs" -timeout=10 -rss_limit_mb=2048 \
    -max_len=4096 -print_final_stats=1 -artifact_prefix=build/fuzz/findings/${h}- \
    ${FUZZ_JOBS:+-jobs=$FUZZ_JOBS -workers=$FUZZ_JOBS} 2>&1 | \
    grep -E "^(stat::|#[0-9]+ *DONE|==[0-9]+==|SUMMARY|.*ERROR|.*deadly)" || true
  ls build/fuzz/findings | grep -q "^$h-" && { echo "fuzz_$h: FINDINGS in build/fuzz/findings"; exit 1; }
done
echo "fuzzing: no findings"
