#!/usr/bin/env bash
# The labeler's benchmark (docs/labeler.md, "Measured"), ground truth as the oracle, on synthetic recordings:
#   1. renders two training recordings (seeds 7 and 8, 300 frames each) and a held-out one (seed 5, 150)
#   2. rdsf-labeler-bench: answers active learning needs to reach the all-labelled model's held-out TAR at
#      FPPF <= 0.1, wrong model answers at --accept/--reject, planted label flips found by the review
#   3. the programs themselves, the truth answering what they ask (--truth-oracle): rdsf-label --loop on the
#      first training recording (one truth file per run: frames are named by index) with a budget of 300
#      answers (17% of its candidates), and rdsf-label --model people on the
#      held-out recording; each prints its wrong model answers and its key-to-next-candidate latency
# Usage: scripts/labeler-bench.sh [--out DIR] (default out/labeler-bench)
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/lib/options.sh
out=out/labeler-bench
script_options labeler-bench --out=out -- "$@"
bin=${RDSF_BUILD_DIR:-build}
mkdir -p "$out"
render() {  # folder seed frames
  [ -f "$out/$1/synth.yml" ] ||
    nice -n 5 "$bin/synth/rdsf-synth" --out "$out/$1" --force --frames "$3" --people 1..4 --seed "$2" --rgb --clip-frames 15 >&2
}
render train 7 300
render train2 8 300
render test 5 150
nice -n 5 "$bin/bench/labeler/rdsf-labeler-bench" --train "$out/train" --train "$out/train2" --test "$out/test" \
  --threads 1 | tee "$out/bench.md"
rm -rf "$out/loop-set" "$out/loop-models" "$out/people-set"
echo "== rdsf-label --loop (truth as the person), budget 300 answers"
nice -n 5 "$bin/labeler/rdsf-label" --source "$out/train" --out "$out/loop-set" --truth "$out/train/boxes.csv" \
  --truth-oracle --loop --batch 50 --budget 300 --models-dir "$out/loop-models" 2>&1 | grep -v "scored" |
  tee "$out/loop.log"
echo "== rdsf-label --model people on the held-out recording (truth as the person)"
nice -n 5 "$bin/labeler/rdsf-label" --source "$out/test" --out "$out/people-set" --model people \
  --truth "$out/test/boxes.csv" --truth-oracle 2>&1 | tee "$out/people.log"
