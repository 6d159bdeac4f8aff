#!/usr/bin/env bash
# Runs every libFuzzer target (or those named) for SECONDS each, one after the other, and prints a
# table of executions and findings; fuzz/fuzz_*.py (the Python module's pickle round trip) run the
# same way on the module in TOPOCUT_PYTHON_PATH (default build/python: the Release build's). Usage:
#   bash fuzz/run.sh SECONDS [BUILD_DIR] [TARGET...]
# Seeds come from fuzz/corpus/<target>/ (committed, small); the grown corpus goes to
# BUILD_DIR/corpus/<target>/ and crash/timeout/oom inputs to BUILD_DIR/findings/<target>/.
# Exit status: non-zero if any target had a finding.
set -uo pipefail
cd "$(dirname "$0")/.."
seconds="${1:?usage: bash fuzz/run.sh SECONDS [BUILD_DIR] [TARGET...]}"
build="${2:-build-fuzz}"
shift $(( $# >= 2 ? 2 : 1 ))
targets=("$@")
if [ "${#targets[@]}" -eq 0 ]; then
  for f in fuzz/fuzz_*.cpp fuzz/fuzz_*.py; do targets+=("$(basename "${f%.*}")"); done
fi
status=0
printf '| target | seconds | executions | exec/s | corpus | findings |\n|---|---|---|---|---|---|\n' > "$build/fuzz_summary.md"
for t in "${targets[@]}"; do
  mkdir -p "$build/corpus/$t" "$build/findings/$t"
  log="$build/findings/$t.log"
  if [ -f "fuzz/$t.py" ]; then  # a crash of the interpreter is the finding; the seed is in the log
    if [ ! -d "${TOPOCUT_PYTHON_PATH:-build/python}/topocut" ]; then
      echo "$t: skipped: no Python module in ${TOPOCUT_PYTHON_PATH:-build/python} (build topocut_python first)"
      continue
    fi
    seed=$RANDOM
    PYTHONPATH="${TOPOCUT_PYTHON_PATH:-build/python}" /usr/bin/python3 "fuzz/$t.py" "$seconds" "$seed" >"$log" 2>&1
    rc=$?
    cat "$log"
    [ "$rc" -ne 0 ] && { status=1; cp "$log" "$build/findings/$t/seed-$seed.log"; }
    runs=$(grep -o '[0-9]* mutated states' "$log" | grep -o '^[0-9]*')
    printf '| %s | %s | %s | %s | - | %s |\n' "$t" "$seconds" "${runs:-?}" "$(( ${runs:-0} / seconds ))" \
      "$(find "$build/findings/$t" -type f | wc -l)" | tee -a "$build/fuzz_summary.md"
    continue
  fi
  # stderr stays visible: libFuzzer's reports (and a sanitizer's, from inside any library) go to the
  # terminal as well as to the log, which is kept.
  "$build/$t" "$build/corpus/$t" "fuzz/corpus/$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -artifact_prefix="$build/findings/$t/" -print_final_stats=1 2>&1 | tee "$log" | grep -v -E '^#[0-9]+\s+(NEW|REDUCE|pulse|INITED)'
  rc=${PIPESTATUS[0]}
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' | tail -1)
  rate=$(grep -o 'stat::average_exec_per_sec: *[0-9]*' "$log" | grep -o '[0-9]*$' | tail -1)
  corpus=$(find "$build/corpus/$t" -type f | wc -l)
  findings=$(find "$build/findings/$t" -type f | wc -l)
  [ "$rc" -ne 0 ] && status=1
  printf '| %s | %s | %s | %s | %s | %s |\n' "$t" "$seconds" "${execs:-?}" "${rate:-?}" "$corpus" "$findings" | tee -a "$build/fuzz_summary.md"
done
exit "$status"
