#!/usr/bin/env bash
# The report scripts' command lines (CTest report_scripts): --help exits 0 and names its defaults, an
# unknown argument is a usage error (exit 2), a folder without a quality report's data is a one-line
# error naming the folder (exit 1), all before any work.
set -uo pipefail
cd "$(dirname "$0")/.."
fail() { echo "check-report-scripts: $*" >&2; exit 1; }
expect() {  # exit code, pattern of stderr/stdout, command...
  local code=$1 pattern=$2; shift 2
  local output status
  output=$("$@" 2>&1); status=$?
  [ "$status" -eq "$code" ] || fail "$* exited $status, expected $code: $output"
  grep -qE -e "$pattern" <<<"$output" || fail "$* printed no line matching '$pattern': $output"
}
empty=$(mktemp -d); trap 'rm -rf "$empty"' EXIT
for s in quality-report regularisation-sweep adaptation-benchmark loso-report background-report propagation-report; do
  expect 0 "default" "scripts/$s.sh" --help
  expect 2 "unknown argument '--bogus'" "scripts/$s.sh" --bogus
done
expect 2 "--test-frames takes a positive number" scripts/quality-report.sh --test-frames 0
expect 2 "--synthetic takes 0-16" scripts/adaptation-benchmark.sh --synthetic 17
expect 2 "--frames takes a positive number" scripts/propagation-report.sh --frames 0
expect 2 "--seeds takes numbers" scripts/propagation-report.sh --seeds "31 x"
expect 2 "--docs needs the whole report" scripts/quality-report.sh --docs --only levers
expect 2 "--cameras takes kinect1 or mix" scripts/train-default-model.sh --cameras bogus
expect 2 "--cameras mix models are not for --install" scripts/train-default-model.sh --cameras mix --install
expect 1 "^regularisation-sweep: $empty has no quality report's data" scripts/regularisation-sweep.sh --out "$empty"
[ -z "$(ls -A "$empty")" ] || fail "regularisation-sweep wrote into $empty although it refused it"
echo "check-report-scripts: ok"
