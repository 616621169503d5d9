#!/usr/bin/env bash
# The measured half of docs/scaling.md (issue 37): rdsf-train's round on one process (1 and 2 threads) and
# under mpirun with 2 and 3 ranks (1 thread each) on the same sample sets, with each process's peak memory
# (/usr/bin/time's maximum resident set) and, under mpirun, the time in the ranks' collective calls. The sets
# are made as the main job makes them (rdsf-synth, rdsf-mine, rdsf-label --truth) unless they exist. Writes a
# Markdown table to OUT/scaling.md, the logs and each run's model (OUT/models-RUN) beside it.
#   scripts/scaling-measure.sh [--out DIR (default out/scaling)] [--frames N (1200)] [--rounds N (30)] [--depth D (2)]
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/lib/options.sh
out=out/scaling frames=1200 rounds=30 depth=2
script_options scaling-measure --out=out --frames=frames --rounds=rounds --depth=depth -- "$@"
bin=$(cd "${RDSF_BUILD_DIR:-build}" && pwd)
command -v mpirun >/dev/null || { echo "scaling-measure: mpirun is absent (Debian: openmpi-bin)" >&2; exit 1; }
mkdir -p "$out"/{data,sets,logs}
data=$out/data sets=$out/sets logs=$out/logs
[ -f "$data/train/synth.yml" ] || "$bin/synth/rdsf-synth" --out "$data/train" --frames "$frames" --people 1..4 --seed 11 --clip-frames 15 --force >/dev/null
[ -f "$data/empty/synth.yml" ] || "$bin/synth/rdsf-synth" --out "$data/empty" --frames "$frames" --people 1..4 --seed 11 --empty --clip-frames 15 --force >/dev/null
[ -d "$sets/negatives" ] || "$bin/miner/rdsf-mine" --source "$data/empty" --out "$sets/negatives" --depth-only 2>/dev/null
[ -d "$sets/people" ] || "$bin/labeler/rdsf-label" --source "$data/train" --out "$sets/people" --truth "$data/train/boxes.csv" \
  --answers /dev/null --keep-rejected >/dev/null 2>&1
root=""; [ "$(id -u)" -eq 0 ] && root="--allow-run-as-root"
common=(--pos "$sets/people" --neg "$sets/negatives" "$sets/people" --name scaling --rounds "$rounds" --depth "$depth"
        --folds 0 --validation-fraction 0 --group-by block)
# run NAME LAUNCHER THREADS: trains into its own models folder; peak memory per process in the log.
run() {
  local name=$1 launcher=$2 threads=$3
  rm -rf "$out/models-$name"
  # shellcheck disable=SC2016
  $launcher sh -c 'exec /usr/bin/time -f "peak_kb ${OMPI_COMM_WORLD_RANK:-0} %M user_s %U wall_s %e" "$@"' sh \
    "$bin/trainer/rdsf-train" "${common[@]}" --threads "$threads" --models-dir "$out/models-$name" >"$logs/$name.log" 2>&1
}
mean_round_ms() { grep -o '[0-9]* ms/round' "$1" | awk '{ s += $1; n++ } END { printf "%.1f", s / n }'; }
peaks() { grep -o 'peak_kb [0-9]* [0-9]*' "$1" | sort -k2n | awk '{ printf "%s%.0f", (NR > 1 ? " / " : ""), $3 / 1024 }'; }
echo "| run | rows per rank | round (ms, mean of $rounds) | in collective calls | peak memory per process (MiB) |" >"$out/scaling.md"
echo "| --- | --- | --- | --- | --- |" >>"$out/scaling.md"
for pass in 1 2; do
  for spec in "one-2threads::2" "one-1thread::1" "ranks-2:mpirun $root --oversubscribe --bind-to none -np 2:1" \
              "ranks-3:mpirun $root --oversubscribe --bind-to none -np 3:1"; do
    IFS=: read -r name launcher threads <<<"$spec"
    echo "scaling-measure: pass $pass: $name" >&2
    run "$name" "$launcher" "$threads"
    rows=$(grep -o 'rank 0 holds [0-9]* of the [0-9]*' "$logs/$name.log" | awk '{ print $4 " of " $7 }' || true)
    coll=$(grep -o '[0-9.]* s in them' "$logs/$name.log" | awk '{ print $1 " s" }' || true)
    echo "| $name (pass $pass) | ${rows:-all} | $(mean_round_ms "$logs/$name.log") | ${coll:--} | $(peaks "$logs/$name.log") |" >>"$out/scaling.md"
  done
done
cat "$out/scaling.md"
