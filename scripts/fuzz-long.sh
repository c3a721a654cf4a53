#!/usr/bin/env bash
# Runs every fuzz target for a long budget with a persistent corpus outside
# the repository (docs/testing.md "Running the fuzzers long").
#
# usage: fuzz-long.sh HOURS [BUILD] [CORPUS]
#   HOURS   wall-clock budget of the whole run, shared evenly by the targets
#           (fractions allowed: 0.5)
#   BUILD   the sanitizer + fuzz build (default build-asan, made by
#           scripts/ci-sanitize.sh or cmake -DFURROW_FUZZ=ON)
#   CORPUS  the persistent corpus (default ${XDG_CACHE_HOME:-~/.cache}/furrow-fuzz):
#           CORPUS/<target>/ grows from run to run; crashes land in
#           CORPUS/crashes/. Start from the seeds of BUILD/fuzz/corpus/.
# FUZZ_JOBS=N runs N targets at a time (default 1: the machine is shared).
# Exits 1 when any target crashed in this run; the inputs are in CORPUS/crashes/.
set -euo pipefail
cd "$(dirname "$0")/.."
hours=${1:?usage: fuzz-long.sh HOURS [BUILD] [CORPUS]}
build=${2:-build-asan}
corpus=${3:-${XDG_CACHE_HOME:-$HOME/.cache}/furrow-fuzz}
jobs=${FUZZ_JOBS:-1}
root=$PWD

targets=("$build"/fuzz_*)
[ -x "${targets[0]}" ] || { echo "fuzz-long: no fuzz targets in $build (build with -DFURROW_FUZZ=ON)" >&2; exit 2; }
per_target=$(awk -v h="$hours" -v n=${#targets[@]} -v j="$jobs" 'BEGIN { printf "%d", h * 3600 * j / n }')
[ "$per_target" -ge 10 ] || { echo "fuzz-long: $hours h is too short for ${#targets[@]} targets" >&2; exit 2; }
echo "fuzz-long: ${#targets[@]} targets, ${per_target} s each, $jobs at a time, corpus $corpus"

export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS=suppressions=$root/scripts/lsan.supp:print_suppressions=0
mkdir -p "$corpus/crashes" "$corpus/logs"
stamp=$(mktemp)
trap 'rm -f "$stamp"' EXIT

run_one() {
  local exe=$1 name=${1##*/fuzz_}
  mkdir -p "$corpus/$name"
  local dict=()
  if [[ $name == *_json ]]; then dict=(-dict="$build/fuzz/corpus/json.dict"); fi
  # -max_len=65536: the default is the largest seed (a few KB); bugs that
  # need a long line or a long array (docs/testing.md) need longer inputs.
  # -fork keeps fuzzing after a crash (each one is saved) and after an
  # out-of-memory or timeout input, which a long unattended run needs.
  "$exe" "${dict[@]}" -fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
    -max_len=65536 -max_total_time="$per_target" -rss_limit_mb=2048 -timeout=10 -print_final_stats=1 \
    -artifact_prefix="$corpus/crashes/$name-" \
    "$corpus/$name" "$build/fuzz/corpus/$name" > "$corpus/logs/$name.log" 2>&1 || true
  local last
  # Fork mode's progress lines ("#N: cov: ...") can share a line with
  # NEW_FUNC reports; keep only the progress part.
  last=$(grep -oE '#[0-9]+: cov: .*' "$corpus/logs/$name.log" | tail -n 1 || true)
  echo "fuzz-long: $name: ${last:-no progress line}"
}

running=0
for exe in "${targets[@]}"; do
  run_one "$exe" &
  running=$((running + 1))
  if [ "$running" -ge "$jobs" ]; then wait -n; running=$((running - 1)); fi
done
wait

# Only this run's findings count; older ones stay in crashes/ until removed.
new=$(find "$corpus/crashes" -type f -newer "$stamp")
if [ -n "$new" ]; then
  echo "fuzz-long: crashing inputs found in this run:"
  echo "$new"
  exit 1
fi
echo "fuzz-long: no crashes"
