#!/usr/bin/env bash
# Fuzzes the parsers that read user files (fuzz/fuzz_<name>.cpp) with libFuzzer, one target at a time, for a
# bounded time each, and prints one summary line per target. See docs/fuzzing.md.
#
#   scripts/fuzz.sh [target ...]        targets by parser name (ground_truth, model_file, ...); default all
#
# Environment:
#   FUZZ_SECONDS   seconds of fuzzing per target (default 60)
#   FUZZ_JOBS      build parallelism (default 2)
#   FUZZ_BUILD     build folder (default build-fuzz in the source tree)
#   FUZZ_MAX_CRASHES  stop a target after this many crashes (default 5); after each crash the target is
#                  restarted for the rest of its time
#
# Found inputs go to $FUZZ_BUILD/artifacts/<name>/ (crash-*, timeout-*, oom-*, leak-*); copy the minimised ones
# (the fuzz target with -minimize_crash=1 -runs=10000 <file>) to fuzz/regressions/<name>/ once fixed.
# The corpus grown while fuzzing stays in $FUZZ_BUILD/corpus/<name>/; fuzz/corpus/<name>/ holds the seeds and
# is never written. Exit status: 0 when no target crashed, 1 when one did, 2 on a build or usage problem.
set -euo pipefail

source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
all_targets=(ground_truth sample_tsv manifest thesis_text model_file answer_journal depth_crop model_writer recipe bag camera_yml adapt_state adaptation_results compressed_image)
if [ "${1:-}" = --help ] || [ "${1:-}" = -h ]; then
  cat <<USAGE
Usage: scripts/fuzz.sh [TARGET ...]   (default: every target; see docs/fuzzing.md)
  TARGET  a parser's fuzz target: ${all_targets[*]}
Environment (defaults): FUZZ_SECONDS seconds per target (60), FUZZ_JOBS build jobs (2), FUZZ_BUILD build
folder (build-fuzz), FUZZ_MAX_CRASHES crashes before a target stops (5). Exit 0: no crash; 1: a crash; 2: a
build or usage problem.
USAGE
  exit 0
fi
seconds="${FUZZ_SECONDS:-60}"
jobs="${FUZZ_JOBS:-2}"
build="${FUZZ_BUILD:-$source_dir/build-fuzz}"
max_crashes="${FUZZ_MAX_CRASHES:-5}"

if ! [[ "$seconds" =~ ^[0-9]+$ ]] || [ "$seconds" -lt 1 ]; then
  echo "fuzz.sh: FUZZ_SECONDS must be a whole number of seconds >= 1, not '$seconds'" >&2
  exit 2
fi
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=("${all_targets[@]}")
for t in "${targets[@]}"; do
  if [ ! -f "$source_dir/fuzz/fuzz_$t.cpp" ]; then
    echo "fuzz.sh: no fuzz target '$t' (known: ${all_targets[*]})" >&2
    exit 2
  fi
done
# clang and its libFuzzer/sanitizer runtime come from Debian; install them when missing.
if ! command -v clang++ > /dev/null || ! dpkg-query -W -f='${Status}' libclang-rt-14-dev 2>/dev/null | grep -q "ok installed"; then
  echo "fuzz.sh: installing clang and libclang-rt-14-dev" >&2
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq clang libclang-rt-14-dev > /dev/null
fi
for tool in clang clang++; do
  command -v "$tool" > /dev/null || { echo "fuzz.sh: $tool not found (apt-get install clang)" >&2; exit 2; }
done

echo "fuzz.sh: configuring $build (clang, RDSF_FUZZ=ON)" >&2
CC=clang CXX=clang++ cmake -S "$source_dir" -B "$build" -DCMAKE_BUILD_TYPE=Debug -DRDSF_FUZZ=ON \
  -DRDSF_BUILD_TESTS=OFF -DRDSF_BUILD_BENCH=OFF > "$build.configure.log" 2>&1 ||
  { cat "$build.configure.log" >&2; echo "fuzz.sh: configure failed" >&2; exit 2; }
if ! grep -q 'CMAKE_CXX_COMPILER_ID:.*Clang\|CMAKE_CXX_COMPILER:.*clang' "$build/CMakeCache.txt"; then
  echo "fuzz.sh: $build was configured with another compiler; remove it and run again" >&2
  exit 2
fi
build_targets=()
for t in "${targets[@]}"; do build_targets+=(--target "fuzz_$t"); done
echo "fuzz.sh: building ${targets[*]}" >&2
cmake --build "$build" -j "$jobs" "${build_targets[@]}" > "$build/build.log" 2>&1 ||
  { tail -n 40 "$build/build.log" >&2; echo "fuzz.sh: build failed (log: $build/build.log)" >&2; exit 2; }

status=0
summary=()
for t in "${targets[@]}"; do
  binary="$build/fuzz/fuzz_$t"
  corpus="$build/corpus/$t"
  artifacts="$build/artifacts/$t"
  scratch="$build/tmp/$t"
  mkdir -p "$corpus" "$artifacts" "$scratch"
  log="$build/fuzz_$t.log"
  : > "$log"
  executions=0
  crashes=0
  started=$(date +%s)
  echo "fuzz.sh: fuzzing $t for $seconds s (log: $log)" >&2
  while true; do
    left=$((seconds - ($(date +%s) - started)))
    [ "$left" -lt 1 ] && break
    run_log="$build/fuzz_$t.run.log"
    set +e
    TMPDIR="$scratch" "$binary" "$corpus" "$source_dir/fuzz/corpus/$t" -max_total_time="$left" -timeout=10 \
      -rss_limit_mb=2048 -max_len=16384 -print_final_stats=1 -artifact_prefix="$artifacts/" > "$run_log" 2>&1
    code=$?
    set -e
    cat "$run_log" >> "$log"
    # Executions: the final statistics when printed, otherwise the last progress line (#N ...).
    runs=$(sed -n 's/^stat::number_of_executed_units: *\([0-9]*\).*/\1/p' "$run_log" | tail -n 1)
    [ -z "$runs" ] && runs=$(sed -n 's/^#\([0-9][0-9]*\)[^0-9].*/\1/p' "$run_log" | tail -n 1)
    executions=$((executions + ${runs:-0}))
    [ "$code" -eq 0 ] && break
    crashes=$((crashes + 1))
    status=1
    artifact=$(sed -n 's/.*Test unit written to \(.*\)$/\1/p' "$run_log" | tail -n 1)
    echo "fuzz.sh: $t crashed (exit $code): ${artifact:-see $log}" >&2
    grep -m 3 -E '^==[0-9]+==ERROR|runtime error|SUMMARY|uncaught exception|deadly signal|timeout' "$run_log" >&2 || true
    [ "$crashes" -ge "$max_crashes" ] && break
  done
  elapsed=$(($(date +%s) - started))
  line=$(printf '%-16s %10d executions in %4d s (%d/s), %d crashes, corpus %d files' "$t" "$executions" \
    "$elapsed" "$((executions / (elapsed > 0 ? elapsed : 1)))" "$crashes" "$(ls "$corpus" | wc -l)")
  summary+=("$line")
  echo "$line"
done

echo "---- summary ($seconds s per target; artifacts in $build/artifacts/) ----"
printf '%s\n' "${summary[@]}"
exit "$status"
