#!/usr/bin/env bash
# The two feature specs on the same data: rdsf (the thesis's 8128 cell pairs) and rdsf-rect (the paper's
# 120,786 square pairs). Renders the main job's quick recordings (training seed 11, people-free seed 11,
# held-out test seed 31), mines and labels them once per spec (the crops are the same bytes: only the
# manifests' spec differs), trains hugeTree-scaled models on each and validates them on the sets labelled
# from the held-out recording. Prints time per round and held-out AUC per spec.
#   scripts/feature-spec-compare.sh [--out DIR] [--scale S] [--rounds N] [--pool N]
# Defaults: --out out/feature-spec-compare --scale 0.3 --rounds 100 --pool 0.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/lib/options.sh
out=out/feature-spec-compare scale=0.3 rounds=100 pool=0
script_options feature-spec-compare --out=out --scale=scale --rounds=rounds --pool=pool -- "$@"
bin=${RDSF_BUILD_DIR:-build}
synth=$bin/synth/rdsf-synth mine=$bin/miner/rdsf-mine label=$bin/labeler/rdsf-label train=$bin/trainer/rdsf-train
data=$out/data
mkdir -p "$data"
render() {
  local name=$1; shift
  [ -f "$data/$name/synth.yml" ] || "$synth" --out "$data/$name" --force "$@" >/dev/null
}
render train --frames 900 --people 1..4 --seed 11 --rgb --clip-frames 15
render empty --frames 500 --people 1..4 --seed 11 --empty --rgb --clip-frames 15
render test --frames 240 --people 1..4 --seed 31 --rgb --clip-frames 60
count() { awk -v s="$1" -v r="$2" 'BEGIN { printf "%d", s * r + 0.5 }'; }
for spec in rdsf rdsf-rect; do
  sets=$out/sets-$spec
  mkdir -p "$sets"
  [ -f "$sets/negatives/manifest.yml" ] || "$mine" --source "$data/empty" --out "$sets/negatives" --feature-spec "$spec" 2>/dev/null
  [ -f "$sets/people/manifest.yml" ] || "$label" --source "$data/train" --out "$sets/people" --truth "$data/train/boxes.csv" \
    --answers /dev/null --keep-rejected --feature-spec "$spec" 2>/dev/null
  [ -f "$sets/test/manifest.yml" ] || "$label" --source "$data/test" --out "$sets/test" --truth "$data/test/boxes.csv" \
    --answers /dev/null --keep-rejected --feature-spec "$spec" 2>/dev/null
  log=$out/train-$spec.log
  /usr/bin/time -v "$train" --name "hugeTree-$spec" --models-dir "$out/models" --pos "$sets/people" \
    --neg "$sets/negatives" "$sets/people" --positives "$(count 5628 "$scale")" --negatives "$(count 22454 "$scale")" \
    --rounds "$rounds" --validation-pos "$sets/test" --validation-neg "$sets/test" --feature-pool "$pool" 2> "$log"
  per_round=$(grep -oE '[0-9]+ ms/round' "$log" | awk '{ s += $1; n++ } END { if (n) printf "%.0f", s / n }')
  echo "$spec: $(grep -E 'positives, .* negatives x' "$log" | sed 's/rdsf-train: //'); $per_round ms per round (mean);" \
       "$(grep -E 'validation AUC' "$log" | sed 's/rdsf-train: //'); peak RSS $(awk '/Maximum resident/ { printf "%.0f MB", $6 / 1024 }' "$log")"
done
