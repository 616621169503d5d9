#!/usr/bin/env bash
# The performance report (issue 9): builds rdsf-perf-report if needed (scripts/setup.sh on a fresh
# checkout, else just that program), runs it and writes its Markdown table.
#
#   scripts/perf-report.sh            full run (about 5-10 minutes on 2 cores) -> docs/perf-report.md
#   scripts/perf-report.sh --quick    smoke run in well under a minute -> $build_dir/perf-report-quick.md
#   scripts/perf-report.sh --out FILE [program options...]   (rdsf-perf-report's options follow below)
#
# The report at the default place is the project's latest table and is replaced on every full run; any
# other --out is refused when it exists unless --force is given. Build folder: $RDSF_BUILD_DIR or build.
# The whole script is one block, read before any of it runs (a run takes minutes; bash reads a plain script as it
# goes, so editing this file during a run would change what the run does next).
{
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/lib/options.sh

build_dir="${RDSF_BUILD_DIR:-build}"
program="$build_dir/bench/report/rdsf-perf-report"

usage() {
  script_header
  if [ -x "$program" ]; then echo; "$program" --help; else echo "($program is not built yet: its options are in docs/options.md)"; fi
}
quick=0
out=""
script_options perf-report --out=out '*' -- "$@"
args=("${script_rest[@]}")
for a in "${args[@]}"; do [ "$a" != --quick ] || quick=1; done
if [ -z "$out" ]; then
  if ((quick)); then out="$build_dir/perf-report-quick.md"; else out="docs/perf-report.md"; fi
  args+=(--force)  # the default report is regenerated on every run
fi

if [ ! -x "$program" ]; then
  echo "perf-report: $program is not built: running scripts/setup.sh" >&2
  scripts/setup.sh
else
  echo "perf-report: bringing $program up to date" >&2
  cmake --build "$build_dir" -j"$(nproc 2>/dev/null || echo 2)" --target rdsf-perf-report >/dev/null
fi

echo "perf-report: load average before the run: $(cut -d' ' -f1-3 /proc/loadavg)" >&2
"$program" --out "$out" "${args[@]}"
exit
}
