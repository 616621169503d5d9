#!/usr/bin/env bash
# The main job: the whole workbench on its embedded default data, from nothing to measured models.
#   1. render synthetic recordings with people (training and held-out test) and people-free ones
#   2. mine negatives from the people-free recordings (then, after the first model, hard negatives)
#   3. label positives in assisted mode from the synthetic ground truth (headless)
#   4. train the thesis's recipes (tree, tree2, hugeTree, treeLast), scaled down unless --full
#   5. evaluate every model on the held-out synthetic sequence and on real frames when present
#   6. print a summary table and write a Markdown report with the ROC and DET charts
# Everything goes under one folder (default out/main-job). Recordings and sample sets are reused by a rerun
# (rendering is deterministic, mining and labelling resume), models get new versions, and every run's
# report goes to its own runs/<time>/ folder: a rerun never clobbers an earlier run's models or report.
# The whole script is one block, read before any of it runs (a run takes minutes; bash reads a plain script as it
# goes, so editing this file during a run would change what the run does next).
{
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/lib/options.sh

usage() {
  cat <<USAGE
Usage: scripts/main-job.sh [--out DIR] [--full] [--real DIR] [--no-real]
  --out DIR    output folder (default out/main-job)
  --full       the thesis's full recipe sizes (2814-5628 positives, 7484-22454 negatives; more frames)
  --real DIR   a folder of real frames with boxes.csv to evaluate on (default ../shared/realdata/people)
  --no-real    skip the real-frame evaluation
USAGE
}
out=out/main-job
full=0
real=../shared/realdata/people
script_options main-job --out=out --full=full=1 --real=real --no-real=real= -- "$@"

started=$(date +%s)
step() { printf '\n== [%s/6] %s (%ds)\n' "$1" "$2" "$(( $(date +%s) - started ))"; }

step 0 "set-up: packages and build"
scripts/setup.sh
bin=${RDSF_BUILD_DIR:-build}
synth=$bin/synth/rdsf-synth mine=$bin/miner/rdsf-mine label=$bin/labeler/rdsf-label
train=$bin/trainer/rdsf-train detect=$bin/detector/rdsf-detect

if ((full)); then
  frames_train=3000 frames_empty=2500 frames_test=600 scale=1 rounds=200
else
  frames_train=900 frames_empty=500 frames_test=240 scale=0.3 rounds=100
fi
data=$out/data sets=$out/sets models=$out/models
run=$out/runs/$(date -u +%Y%m%dT%H%M%SZ)
mkdir -p "$data" "$sets" "$models" "$run"

step 1 "render synthetic recordings"
render() {  # name, options...: skipped when already complete (same seed, same bytes)
  local name=$1; shift
  if [ -f "$data/$name/synth.yml" ]; then echo "$data/$name: already rendered"; return; fi
  "$synth" --out "$data/$name" --force "$@"
}
render train --frames "$frames_train" --people 1..4 --seed 11 --rgb --clip-frames 15
render empty --frames "$frames_empty" --people 1..4 --seed 11 --empty --rgb --clip-frames 15 # the training rooms, no people
render empty-hard --frames "$frames_empty" --people 0..0 --seed 21 --empty --rgb --clip-frames 15 # other rooms
render test --frames "$frames_test" --people 1..4 --seed 31 --rgb --clip-frames 60 # held out: other rooms, people

step 2 "mine negatives from the people-free recordings"
"$mine" --source "$data/empty" --out "$sets/negatives"

step 3 "label positives (assisted by the ground truth, headless)"
# Candidates overlapping a person with IoU >= 0.5 are positives, below 0.3 negatives (kept: hard negatives
# next to people); the uncertain band in between stays unanswered (no answers given).
"$label" --source "$data/train" --out "$sets/people" --truth "$data/train/boxes.csv" --answers /dev/null \
  --keep-rejected

count() { awk -v s="$1" -v r="$2" 'BEGIN { printf "%d", s * r + 0.5 }'; }
train_recipe() {  # recipe, negative sets...
  local recipe=$1; shift
  local pos neg
  case "$recipe" in
    tree) pos=2814 neg=7484 ;; tree2) pos=4028 neg=7484 ;;
    hugeTree) pos=5628 neg=22454 ;; treeLast) pos=1115 neg=10085 ;;
  esac
  "$train" --recipe "models/recipes/$recipe.yml" --models-dir "$models" --pos "$sets/people" --neg "$@" \
    --positives "$(count "$pos" "$scale")" --negatives "$(count "$neg" "$scale")" --rounds "$rounds" --group-by block
}

step 4 "train the recipes (scale $scale of the thesis's sample counts, $rounds rounds)"
train_recipe tree "$sets/negatives" "$sets/people"
echo "-- hard-negative round: the first model's false positives on other people-free rooms"
"$mine" --source "$data/empty-hard" --out "$sets/hard-negatives" --model tree --models-dir "$models" --min-score 0
train_recipe tree2 "$sets/negatives" "$sets/hard-negatives" "$sets/people"
train_recipe hugeTree "$sets/negatives" "$sets/hard-negatives" "$sets/people"
train_recipe treeLast "$sets/negatives" "$sets/hard-negatives" "$sets/people"

step 5 "evaluate on the held-out synthetic sequence$([ -n "$real" ] && [ -f "$real/boxes.csv" ] && echo ' and on real frames')"
evaluate() {  # source, truth, report folder
  "$detect" --source "$1" --truth "$2" --report-dir "$3" --models-dir "$models" --clip-frames 60 \
    --model tree --model tree2 --model hugeTree --model treeLast --save-dir "$3/frames" \
    >/dev/null
}
evaluate "$data/test" "$data/test/boxes.csv" "$run/synthetic"
have_real=0
if [ -n "$real" ] && [ -f "$real/boxes.csv" ]; then
  evaluate "$real" "$real/boxes.csv" "$run/real"
  have_real=1
elif [ -n "$real" ]; then
  echo "main-job: $real/boxes.csv not found: no real-frame evaluation (--real DIR names another folder)" >&2
fi

step 6 "summary"
report=$run/REPORT.md
{
  echo "# Main job report ($(date -u +%Y-%m-%dT%H:%M:%SZ))"
  echo
  echo "Synthetic data: $frames_train training frames, $frames_empty people-free frames (+ $frames_empty for hard"
  echo "negatives), $frames_test held-out test frames; recipes at scale $scale of the thesis's sample counts,"
  echo "$rounds rounds. Sample sets: $(ls "$sets" | tr '\n' ' '); models under \`$models\`."
  echo
  echo "## Held-out synthetic sequence"
  echo
  cat "$run/synthetic/summary.md"
  echo
  echo '![ROC](synthetic/roc.png) ![DET](synthetic/det.png)'
  echo
  if ((have_real)); then
    echo "## Real frames ($real)"
    echo
    cat "$run/real/summary.md"
    echo
    echo '![ROC](real/roc.png) ![DET](real/det.png)'
    echo
  fi
  echo "Full tables (TAR, FAR, TRR, FRR, n_fp, n_det, FPPF, n_miss, MPF, MOTA, MOTP per threshold, with and"
  echo "without segmentation errors): \`synthetic/summary.txt\`$( ((have_real)) && echo ', `real/summary.txt`'),"
  echo "and \`metrics.csv\` beside them; pictures of every frame under \`*/frames/\`."
} > "$report.partial"
mv "$report.partial" "$report"

echo
echo "Held-out synthetic sequence:"
cat "$run/synthetic/summary.md"
if ((have_real)); then echo; echo "Real frames ($real):"; cat "$run/real/summary.md"; fi
echo
echo "main-job: done in $(( $(date +%s) - started )) s. Report: $report"
exit
}
