#!/usr/bin/env bash
# Whole rooms labelled with the truth as the person (docs/adapting-to-your-room.md, "Within the image"): for each
# seed, 16 synthetic rooms (rdsf-synth --frames 960 --people 1..4 --clip-frames 60 --seed S) labelled by
# rdsf-label --ask uncertain with the shipped model, every question answered by the truth (--truth-oracle), in
# four ways: per candidate, and per track with the model's tracks off, within the image and anywhere. The table:
# answers (and how many times fewer than per candidate), and the labels written along tracks and places that the
# truth contradicts. Renderings under --out are reused when complete.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/lib/options.sh
usage() {
  cat <<'USAGE'
scripts/propagation-report.sh [--seeds "S ..."] [--frames N] [--out DIR]
  --seeds "S ..."  rdsf-synth seeds, one set of rooms each (default "31 32 33 34")
  --frames N       frames a set, 60 a room (default 960: 16 rooms)
  --out DIR        renderings, sample sets, logs and REPORT.md (default out/propagation)
Programs: $RDSF_BUILD_DIR (default build/): synth/rdsf-synth, labeler/rdsf-label; the model people/v2 of models/.
USAGE
}
seeds="31 32 33 34" frames=960 out=out/propagation
script_options propagation-report.sh --seeds=seeds --frames=frames --out=out -- "$@"
[[ "$frames" =~ ^[1-9][0-9]*$ ]] || { echo "propagation-report.sh: usage error: --frames takes a positive number" >&2; exit 2; }
[[ "$seeds" =~ ^[0-9]+( [0-9]+)*$ ]] || { echo "propagation-report.sh: usage error: --seeds takes numbers" >&2; exit 2; }
bin=${RDSF_BUILD_DIR:-build}
for p in synth/rdsf-synth labeler/rdsf-label; do
  [ -x "$bin/$p" ] || { echo "propagation-report.sh: $bin/$p is missing: build it first" >&2; exit 1; }
done
mkdir -p "$out"

# Numbers of rdsf-label's closing lines (0 when the line is not there: the model's tracks off).
first_match() { local n; n=$(sed -n "$2" "$1" | tail -1); echo "${n:-0}"; }
answers() { first_match "$1" 's/^rdsf-label: [0-9]* frames; answered \([0-9]*\) .*/\1/p'; }
labels() { first_match "$1" "s/^rdsf-label: $2: \([0-9]*\) labels propagated.*/\1/p"; }
wrong() { first_match "$1" "s/^rdsf-label: $2: .*the truth contradicts \([0-9]*\) .*/\1/p"; }

report=$out/REPORT.md
{
  echo "# Whole rooms labelled with the truth as the person ($(date -u +%Y-%m-%dT%H:%MZ))"
  echo
  echo "scripts/propagation-report.sh --seeds \"$seeds\" --frames $frames: answers (times fewer than per candidate);"
  echo "wrong = labels along tracks and places that the truth contradicts, of all written that way."
  echo
  echo "| rooms | per candidate | per track, model's tracks off | model's tracks within the image | model's tracks anywhere |"
  echo "| --- | --- | --- | --- | --- |"
} > "$report.tmp"
for seed in $seeds; do
  rooms=$out/rooms-$seed
  if [ ! -f "$rooms/.complete" ]; then
    echo "propagation-report: rendering seed $seed ($frames frames)" >&2
    "$bin/synth/rdsf-synth" --out "$rooms" --force --frames "$frames" --people 1..4 --clip-frames 60 --seed "$seed" \
      >/dev/null 2>"$out/synth-$seed.log" || { tail -3 "$out/synth-$seed.log" >&2; exit 1; }
    touch "$rooms/.complete"
  fi
  row="| seed $seed"
  base=0
  for mode in candidate off within anywhere; do
    args=()
    case $mode in
      off) args=(--per-track --propagate-model-answers off) ;;
      within) args=(--per-track --propagate-model-answers on --model-track-within-image on) ;;
      anywhere) args=(--per-track --propagate-model-answers on --model-track-within-image off) ;;
    esac
    log=$out/label-$seed-$mode.log
    rm -rf "$out/set-$seed-$mode"
    echo "propagation-report: seed $seed, $mode" >&2
    "$bin/labeler/rdsf-label" --source "$rooms" --out "$out/set-$seed-$mode" --model people --models-dir models \
      --ask uncertain --keep-rejected --truth "$rooms/boxes.csv" --truth-oracle --threads 2 "${args[@]}" \
      >/dev/null 2>"$log" || { tail -3 "$log" >&2; exit 1; }
    n=$(answers "$log")
    if [ "$mode" = candidate ]; then
      base=$n
      row="$row | $n"
      continue
    fi
    written=$(( $(labels "$log" "per track") + $(labels "$log" "model answers' tracks") ))
    bad=$(( $(wrong "$log" "per track") + $(wrong "$log" "model answers' tracks") ))
    row="$row | $n ($(awk -v a="$base" -v b="$n" 'BEGIN { printf "%.1fx", b ? a / b : 0 }')); $bad of $written wrong ($(awk -v a="$bad" -v b="$written" 'BEGIN { printf "%.2f %%", b ? 100 * a / b : 0 }'))"
  done
  echo "$row |" >> "$report.tmp"
done
mv "$report.tmp" "$report"
cat "$report"
