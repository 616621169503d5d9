#!/usr/bin/env bash
# The quality report: how well the detectors this workbench trains find people in recordings they have
# never seen, and whether the figures the trainer prints predict it.
#   1. renders (or reuses) the main job's synthetic recordings: training (seed 11), the same rooms empty,
#      other empty rooms (seed 21) and the held-out test sequence (seed 31: other rooms, other people;
#      --test-frames, default 960 = 16 rooms of 60 frames; its first 240 frames are the main job's sequence)
#   2. mines negatives and labels positives from the training recordings (as the main job)
#   3. the lever table: one recipe (tree2 at the main job's scale) trained with each training lever added
#      in turn (thesis baseline, group validation + calibration, regularisation, trees, augmentation,
#      iterated hard-negative bootstrapping), each evaluated on the held-out sequence and on real frames
#   4. the recipes table: the four recipes with the chosen defaults, evaluated the same way
#   5. the shipped default models (models/people/v*.yml, trained by scripts/train-default-model.sh on their
#      own synthetic rooms), evaluated the same way (whole runs and --only shipped); a model that states
#      detection options (people/v4: --local-front 70) runs with them and so scores other candidates: it is
#      evaluated on its own, the models stating none together
#   6. the peer row: PCL's ground-based people detector (peers/pcl_people, rdsf-pcl-people; libpcl-dev is
#      installed here, CI does not need it) on the real frames with colour, beside the shipped models on the
#      same frames (whole runs and --only shipped; --no-peer skips it)
# Real frames are reported per source (the frames' name prefixes: lab_ = UC3M lab, lab_height included, and
# home_ = UC3M home; docs/quality.md, "Per source") and pooled, and so are the labelled public sources of
# datasets/public (a corridor, a hall), which are in the repository and need no ../shared.
# Each evaluation prints one row per model: TAR at FPPF <= 0.1 and <= 0.5 (exact curve), best MOTA,
# candidate recall, the classifier's AUC on the candidates, and the gap between the TAR the model file's
# validation predicts at its operating point (P >= 0.5 unless the model states one) and the TAR measured on
# the held-out candidates.
# Everything goes under out/quality (--out); the tables are collected in REPORT.md there.
# The whole script is one block, read before any of it runs (a run takes minutes; bash reads a plain script as it
# goes, so editing this file during a run would change what the run does next).
{
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/lib/options.sh

usage() {
  cat <<USAGE
Usage: scripts/quality-report.sh [--out DIR] [--real DIR] [--no-real] [--only levers|recipes|shipped] [--test-frames N]
                                [--synth-variety 'RDSF-SYNTH OPTIONS'] [--no-peer] [--docs]
  --out DIR      output folder (default out/quality); recordings and sample sets there are reused (the
                 hard negatives and lever models are made again: a rerun gives a fresh run's figures)
  --test-frames N  frames of the held-out synthetic sequence (default 960: 16 rooms of 60 frames; 4 rooms,
                 the main job's 240 frames, make single figures noisy); its first 240 frames are also
                 reported on their own when N > 240
  --docs         also write the report to docs/quality-report.md (the checked-in results; a whole run only)
  --real DIR     real frames with boxes.csv (default ../shared/realdata/people)
  --no-real      skip the real frames
  --only WHAT    run only the lever table, only the recipes table, or only the shipped models and the peer
                 (shipped: renders the held-out sequence alone, trains nothing)
  --synth-variety 'OPTIONS'  extra rdsf-synth options for the TRAINING renderings (training, its empty
                 rooms, the other empty rooms; not the held-out sequence), e.g. a data lever: use another
                 --out (the renderings there are made with them)
  --no-peer      skip the PCL peer row (it installs libpcl-dev, about 1 GB, and builds rdsf-pcl-people)
USAGE
}
out=out/quality
real=../shared/realdata/people
only=""
test_frames=960
docs=0
variety=""
peer=1
script_options quality-report --out=out --real=real --no-real=real= --only=only --test-frames=test_frames --docs=docs=1 --synth-variety=variety --no-peer=peer=0 -- "$@"
case "$only" in ""|levers|recipes|shipped) ;; *) echo "quality-report: --only takes levers, recipes or shipped" >&2; exit 2 ;; esac
if ((docs)) && [ -n "$only" ]; then echo "quality-report: --docs needs the whole report (no --only)" >&2; exit 2; fi
case "$test_frames" in ''|*[!0-9]*|0) echo "quality-report: --test-frames takes a positive number of frames" >&2; exit 2 ;; esac

started=$(date +%s)
step() { printf '\n== %s (%ds)\n' "$1" "$(( $(date +%s) - started ))" >&2; }
scripts/setup.sh >&2
bin=${RDSF_BUILD_DIR:-build}
synth=$bin/synth/rdsf-synth mine=$bin/miner/rdsf-mine label=$bin/labeler/rdsf-label
train=$bin/trainer/rdsf-train detect=$bin/detector/rdsf-detect
data=$out/data sets=$out/sets models=$out/models logs=$out/logs
run=$out/runs/$(date -u +%Y%m%dT%H%M%SZ)
mkdir -p "$data" "$sets" "$models" "$logs" "$run"
have_real=0
if [ -n "$real" ] && [ -f "$real/boxes.csv" ]; then
  have_real=1
elif [ -n "$real" ]; then
  echo "quality-report: $real/boxes.csv not found: no real-frame evaluation (--real DIR names another folder)" >&2
fi

step "render the synthetic recordings (reused when present)"
# A recording is reused only when the generator that made it is the one built now (synth.yml's
# "generator:" line); the recordings render side by side (one process each).
generator=$("$synth" --out "$out/.generator-probe" --force --frames 1 --empty >/dev/null 2>&1 &&
            grep '^generator:' "$out/.generator-probe/synth.yml"; rm -rf "$out/.generator-probe")
render_pids=() render_names=()
render() {
  local name=$1; shift
  if [ -f "$data/$name/synth.yml" ] && grep -qxF "$generator" "$data/$name/synth.yml"; then
    echo "$data/$name: already rendered" >&2; return
  fi
  [ -f "$data/$name/synth.yml" ] && echo "$data/$name: made by another generator, rendering again" >&2
  "$synth" --out "$data/$name" --force "$@" >"$logs/render-$name.log" 2>&1 &
  render_pids+=($!) render_names+=("$name")
}
test=test-$test_frames
read -r -a variety_args <<<"$variety"
if [ "$only" != shipped ]; then  # the training recordings: the shipped models were trained elsewhere
  render train --frames 900 --people 1..4 --seed 11 --rgb --clip-frames 15 "${variety_args[@]}"
  render empty --frames 500 --people 1..4 --seed 11 --empty --rgb --clip-frames 15 "${variety_args[@]}"
  render empty-hard --frames 500 --people 0..0 --seed 21 --empty --rgb --clip-frames 15 "${variety_args[@]}"
fi
render "$test" --frames "$test_frames" --people 1..4 --seed 31 --rgb --clip-frames 60
for i in "${!render_pids[@]}"; do
  wait "${render_pids[$i]}" || { tail -3 "$logs/render-${render_names[$i]}.log" >&2; exit 1; }
  echo "$data/${render_names[$i]}: $(tail -1 "$logs/render-${render_names[$i]}.log")" >&2
done
# Sample sets are made from the recordings: new recordings, new sets.
if ((${#render_pids[@]})); then rm -rf "$sets"; mkdir -p "$sets"; fi
# The main job's held-out sequence is the same generator's first 240 frames: a list file and their boxes.
main_test=""
if ((test_frames > 240)); then
  main_test=$data/$test-first240
  mkdir -p "$main_test"
  (cd "$data/$test" && ls ./*.depth.png | sort | awk "NR <= 240" | sed "s|^\./|../$test/|") > "$main_test/frames.txt"
  awk -F, 'NR == 1 || $1 + 0 < 240' "$data/$test/boxes.csv" > "$main_test/boxes.csv"
fi

# The real frames per source (boxes.csv's frame name prefixes), each a list file and its boxes; *-colour: the
# frames with a colour image (the PCL peer needs colour; the shipped models are evaluated on them too).
# The labelled public sources of datasets/public follow, reported the same way (whether or not ../shared is
# there).
source scripts/real-sources.sh
real_sets=()
if ((have_real)); then
  mapfile -t real_sets < <(real_source_sets "$real" "$out")
fi
mapfile -t public_sets < <(public_source_sets "$out")
real_sets+=("${public_sets[@]}")

if [ "$only" != shipped ]; then
  step "mine negatives and label positives"
  "$mine" --source "$data/empty" --out "$sets/negatives" 2>"$logs/mine.log" || { cat "$logs/mine.log" >&2; exit 1; }
  "$label" --source "$data/train" --out "$sets/people" --truth "$data/train/boxes.csv" --answers /dev/null \
    --keep-rejected 2>"$logs/label.log" || { cat "$logs/label.log" >&2; exit 1; }
fi

# The main job's tree2 at scale 0.3: 1208 positives, 2245 negatives, 100 rounds.
pos=1208 neg=2245
evaluate() {  # report folder, models...
  local dir=$1; shift
  local args=()
  for m in "$@"; do args+=(--model "$m"); done
  # The evaluation sets run side by side (rdsf-detect is one process per set).
  local pids=() names=()
  one() {  # name, source, truth
    "$detect" --source "$2" --truth "$3" --report-dir "$dir/$1" --models-dir "$models" --clip-frames 60 \
      "${args[@]}" --force >/dev/null 2>"$logs/detect-$1.log" &
    pids+=($!) names+=("$1")
  }
  one synthetic "$data/$test" "$data/$test/boxes.csv"
  [ -n "$main_test" ] && one synthetic-240 "$main_test/frames.txt" "$main_test/boxes.csv"
  ((have_real)) && one real "$real" "$real/boxes.csv"
  local set
  for set in "${real_sets[@]}"; do
    case "$set" in *-colour) ((with_colour)) || continue ;; esac
    one "$set" "$out/real-sources/$set/frames.txt" "$out/real-sources/$set/boxes.csv"
  done
  local i
  for i in "${!pids[@]}"; do
    wait "${pids[$i]}" || { cat "$logs/detect-${names[$i]}.log" >&2; exit 1; }
  done
}
train_model() {  # name, extra rdsf-train options...
  local name=$1; shift
  local t0; t0=$(date +%s)
  "$train" --models-dir "$models" --name "$name" --pos "$sets/people" --positives "$pos" --negatives "$neg" \
    --rounds 100 "$@" 2>"$logs/train-$name.log" || { tail -3 "$logs/train-$name.log" >&2; exit 1; }
  grep -E "validation AUC|calibration|wrote" "$logs/train-$name.log" | sed 's/^/  /' >&2
  echo "  trained $name in $(( $(date +%s) - t0 )) s" >&2
}
hard_negatives() {  # model, set: mines the model's false positives on the other empty rooms; prints FPPF
  "$mine" --source "$data/empty-hard" --out "$2" --model "$1" --models-dir "$models" --min-score 0 \
    2>"$logs/mine-hard.log" || { cat "$logs/mine-hard.log" >&2; exit 1; }
  awk '/hard negatives:/ { printf "%.4f", $4 / 500 }' "$logs/mine-hard.log"
}

table_of() {  # report folder, title
  echo "### $2"
  echo
  echo "Held-out synthetic sequence ($test_frames frames, seed 31, $(( (test_frames + 59) / 60 )) rooms):"
  echo
  cat "$1/synthetic/summary.md"
  if [ -n "$main_test" ]; then
    echo
    echo "... its first 240 frames (4 rooms: the main job's held-out sequence):"
    echo
    cat "$1/synthetic-240/summary.md"
  fi
  if ((have_real)); then
    echo
    echo "Real frames ($real), all sources pooled:"
    echo
    cat "$1/real/summary.md"
  fi
  local set
  for set in "${real_sets[@]}"; do
    [ -f "$1/$set/summary.md" ] || continue
    echo
    echo "Real frames, $(source_title "$set") ($(wc -l < "$out/real-sources/$set/frames.txt") frames):"
    echo
    cat "$1/$set/summary.md"
  done
  echo
}
source_title() {
  case "$1" in
    real-lab) echo "source UC3M lab (lab_*, lab_height included)" ;;
    real-home) echo "source UC3M home (home_*)" ;;
    real-lab-colour) echo "source UC3M lab, the frames with colour" ;;
    real-home-colour) echo "source UC3M home, the frames with colour" ;;
    public-corridor) echo "public source PCL corridor (datasets/public/pcl_people: five people, one frame)" ;;
    public-hall) echo "public source TU/e hall (datasets/public/tue_hero: a robot's head camera, one man counted, seated people don't care)" ;;
    *) echo "$1" ;;
  esac
}
with_colour=0

report=$run/REPORT.md
{
  echo "# Quality report ($(date -u +%Y-%m-%dT%H:%M:%SZ), $(nproc) cores)"
  echo
  echo "Training data: the main job's synthetic recordings (900 frames seed 11, negatives from the same rooms"
  echo "empty, hard negatives from other empty rooms seed 21); tree2 counts at scale 0.3 ($pos positives,"
  echo "$neg negatives), 100 rounds. 'TAR at P >= op' compares the model file's validation TAR with the"
  echo "classifier's TAR on the evaluated recording's candidates at the same probability threshold."
  echo
} > "$report"

# A common hard-negative set mined with the thesis baseline, so that every lever trains on the same data.
if [ -z "$only" ] || [ "$only" = levers ]; then
  step "lever table"
  # The hard negatives and the lever models follow the models of this run: made again each time, so that a
  # rerun in the same --out gives the figures of a fresh run (reused hard-negative sets had collected every
  # earlier run's rounds, and an earlier run's L6-boot3 would have been evaluated beside this run's models).
  rm -rf "$sets/hard-L0" "$sets/hard-boot" "$models"/L[0-9]-*
  base_neg=("$sets/negatives" "$sets/people")
  train_model L0-thesis --neg "${base_neg[@]}" --calibration none --group-frames 0 --folds 0 --depth 1 \
    --learning-rate 1 --augment off
  fppf=$(hard_negatives L0-thesis "$sets/hard-L0")
  echo "  hard negatives of L0 on the other empty rooms: FPPF $fppf" >&2
  echo "hard negatives of L0-thesis: FPPF $fppf on the other empty rooms" > "$run/bootstrapping.txt"
  neg_sets=("$sets/negatives" "$sets/hard-L0" "$sets/people")
  # The main job's recordings are in step (frame i of the people and people-free renderings shows the same
  # room), so groups are frame blocks of all recordings together.
  honest=(--group-by block --calibration platt)
  # L1-L4 validate on one held-out fifth of the groups; L5 adds the 5 folds (the trainer's default).
  train_model L1-groups --neg "${neg_sets[@]}" "${honest[@]}" --folds 0 --depth 1 --learning-rate 1 --augment off
  train_model L2-shrinkage --neg "${neg_sets[@]}" "${honest[@]}" --folds 0 --depth 1 --learning-rate 0.5 --augment off
  train_model L3-trees --neg "${neg_sets[@]}" "${honest[@]}" --folds 0 --depth 2 --learning-rate 0.5 --augment off
  train_model L4-mirror --neg "${neg_sets[@]}" "${honest[@]}" --folds 0 --depth 2 --learning-rate 0.5 --augment mirror
  train_model L5-folds --neg "${neg_sets[@]}" "${honest[@]}" --depth 2 --learning-rate 0.5 --augment mirror --folds 5
  # Iterated bootstrapping: mine the newest model's false positives, retrain, until FPPF stops falling.
  last=L5-folds boot_sets=("${neg_sets[@]}" "$sets/hard-boot") prev=""
  for round in 1 2 3 4; do
    fppf=$(hard_negatives "$last" "$sets/hard-boot")
    echo "  bootstrapping round $round: $last has FPPF $fppf on the other empty rooms" >&2
    echo "bootstrapping round $round: $last FPPF $fppf on the other empty rooms" >> "$run/bootstrapping.txt"
    if [ -n "$prev" ] && awk -v a="$fppf" -v b="$prev" 'BEGIN { exit !(a >= 0.9 * b) }'; then break; fi
    prev=$fppf
    train_model "L6-boot$round" --neg "${boot_sets[@]}" "${honest[@]}" --depth 2 --learning-rate 0.5 \
      --augment mirror --folds 5
    last="L6-boot$round"
  done
  lever_models=(L0-thesis L1-groups L2-shrinkage L3-trees L4-mirror L5-folds)
  for m in "$models"/L6-boot*; do [ -d "$m" ] && lever_models+=("$(basename "$m")"); done
  step "evaluate the levers"
  evaluate "$run/levers" "${lever_models[@]}"
  {
    table_of "$run/levers" "Training levers, one after the other (tree2 size)"
    echo "Bootstrapping:"
    echo
    sed 's/^/    /' "$run/bootstrapping.txt"
    echo
  } >> "$report"
fi

if [ -z "$only" ] || [ "$only" = recipes ]; then
  step "recipes with the defaults"
  count() { awk -v s="$1" 'BEGIN { printf "%d", s * 0.3 + 0.5 }'; }
  recipe_neg=("$sets/negatives" "$sets/people")
  [ -d "$sets/hard-boot" ] && recipe_neg+=("$sets/hard-boot")
  [ -d "$sets/hard-L0" ] && recipe_neg+=("$sets/hard-L0")
  for r in tree:2814:7484 tree2:4028:7484 hugeTree:5628:22454 treeLast:1115:10085; do
    IFS=: read -r name p n <<<"$r"
    "$train" --recipe "models/recipes/$name.yml" --models-dir "$models" --pos "$sets/people" --neg "${recipe_neg[@]}" \
      --group-by block \
      --positives "$(count "$p")" --negatives "$(count "$n")" 2>"$logs/train-$name.log" || { tail -3 "$logs/train-$name.log" >&2; exit 1; }
    grep -E "validation AUC|calibration" "$logs/train-$name.log" | sed 's/^/  /' >&2
  done
  step "evaluate the recipes"
  evaluate "$run/recipes" tree tree2 hugeTree treeLast
  table_of "$run/recipes" "The thesis's recipes (scale 0.3) with the workbench's defaults" >> "$report"
fi

if [ -z "$only" ] || [ "$only" = shipped ]; then
  step "evaluate the shipped default models"
  # A model that states detection options (model file format 4) runs with them and scores other candidates
  # than the rest, which rdsf-detect will not score side by side: each such model has a table of its own.
  plain=() stating=()
  for m in models/people/v*.yml; do
    if grep -q '^detection_options:' "$m"; then stating+=("$m"); else plain+=("$m"); fi
  done
  with_colour=1
  ((${#plain[@]})) && evaluate "$run/shipped" "${plain[@]}"
  declare -A states=()  # model file -> its options as rdsf-detect printed them ("--local-front 70")
  for m in "${stating[@]}"; do
    evaluate "$run/shipped-$(basename "$m" .yml)" "$m"
    states[$m]=$(sed -n 's/.*states its detection options (\([^)]*\)).*/\1/p' "$logs/detect-synthetic.log" | head -1)
  done
  with_colour=0
  ((${#plain[@]})) && table_of "$run/shipped" "The shipped default models stating no detection options (scripts/train-default-model.sh: their own synthetic rooms, seed 11)" >> "$report"
  for m in "${stating[@]}"; do
    table_of "$run/shipped-$(basename "$m" .yml)" "The shipped default model people/$(basename "$m" .yml), with the detection options it states (${states[$m]})" >> "$report"
  done
fi

if { [ -z "$only" ] || [ "$only" = shipped ]; } && ((peer)); then
  step "the PCL peer row"
  # PCL is large and only this report needs it: installed here, not by scripts/setup.sh.
  if ! dpkg-query -W -f='${Status}' libpcl-dev 2>/dev/null | grep -q "ok installed"; then
    sudo_=""; [ "$(id -u)" -ne 0 ] && sudo_=sudo
    $sudo_ apt-get install -y --no-install-recommends libpcl-dev >"$logs/apt-pcl.log" 2>&1 ||
      { tail -3 "$logs/apt-pcl.log" >&2; exit 1; }
  fi
  cmake -S . -B "$bin" >/dev/null && cmake --build "$bin" --target rdsf-pcl-people >"$logs/build-pcl.log" 2>&1 ||
    { tail -5 "$logs/build-pcl.log" >&2; exit 1; }
  {
    echo "### The peer: PCL's ground-based people detector"
    echo
    echo "pcl::people::GroundBasedPeopleDetectionApp with PCL's HOG+SVM file (peers/pcl_people), PCL's defaults"
    echo "(person 1.3-2.3 m, voxel 6 cm, a person at confidence >= -1.5), the floor fitted per recording by RANSAC;"
    echo "its confidence is the score (P = 1 / (1 + exp(-2 c)) for the thresholds). On the real frames with colour,"
    echo "beside the shipped models on the same frames (the tables above, '... the frames with colour', and the"
    echo "public hall, every frame of which has colour; not the public corridor, PCL's own test cloud for it):"
    for set in "${real_sets[@]}"; do
      case "$set" in *-colour | public-hall) ;; *) continue ;; esac
      mkdir -p "$run/peer"
      "$bin/peers/pcl_people/rdsf-pcl-people" --source "$out/real-sources/$set/frames.txt" \
        --truth "$out/real-sources/$set/boxes.csv" --report-dir "$run/peer/$set" \
        --out "$run/peer/$set.detections.csv" --force >/dev/null 2>"$logs/peer-$set.log" ||
        { cat "$logs/peer-$set.log" >&2; exit 1; }
      echo
      echo "Real frames, $(source_title "$set") ($(wc -l < "$out/real-sources/$set/frames.txt") frames; $(grep -c "recording '" "$logs/peer-$set.log") recording(s), floors: $(grep -o "camera [0-9.]* m above" "$logs/peer-$set.log" | awk '{printf "%s%.2f", sep, $2; sep=", "}') m below the camera):"
      echo
      cat "$run/peer/$set/summary.md"
    done
    echo
  } >> "$report"
fi

cat "$report"
if ((docs)); then
  { echo "<!-- Generated by scripts/quality-report.sh --docs: do not edit by hand (docs/quality.md explains it). -->"
    echo
    cat "$report"
  } > docs/quality-report.md.tmp
  sync docs/quality-report.md.tmp && mv docs/quality-report.md.tmp docs/quality-report.md
  echo "quality-report: wrote docs/quality-report.md" >&2
fi
echo "quality-report: done in $(( $(date +%s) - started )) s. Report: $report" >&2
exit
}
