#!/usr/bin/env bash
# The resolution report (issue 36, "Any resolution"): what a model trained on one sensor loses on another.
#   1. renders the quality report's held-out synthetic sequence (seed 31, --test-frames, default 960 = 16
#      rooms of 60 frames; the same rooms, people and sensor noise for every camera: rdsf-synth draws the
#      scenes independently of the camera) through each camera of the table below (rdsf-synth --size
#      --fov; the folder's camera.yml gives rdsf-detect the model)
#   2. evaluates the model (--model, default the shipped people/v2) on each: rdsf-detect --truth, the
#      quality report's figures (TAR at FPPF <= 0.1 and <= 0.5 with 95 % intervals over the people,
#      candidate recall, the classifier's AUC on the candidates, best MOTA)
#   3. the lever (--no-lever skips it): two models of the quality report's tree2 size (1208 positives,
#      2245 negatives, 100 rounds, group validation by frame block, Platt calibration, depth-2 trees,
#      shrinkage 0.5, mirror augmentation, 5 folds, then one round of hard negatives mined on other empty
#      rooms and trained again), one on the Kinect v1 renderings only, one on the same scenes with the
#      camera drawn per clip from the training cameras (clip c through camera c mod K: same frames, same
#      rooms, only the camera differs); both evaluated on every rendering, on the real frames per source
#      (UC3M lab lab_*, UC3M home home_*) and on the real frames resized to 512x424, 848x480 and 1280x720
#      (scripts/resized-frames.py: the original's detections found again at IoU >= 0.7, the measure of
#      the test CameraFile.ResizedRealFramesWithTheirCameraModelFindTheSamePeople)
# Everything goes under out/resolution (--out); recordings, sample sets and models there are reused when
# their inputs did not change; the tables are collected in REPORT.md there.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/lib/options.sh

usage() {
  cat <<USAGE
Usage: scripts/resolution-report.sh [--out DIR] [--test-frames N] [--model M] [--real DIR] [--no-real]
                                   [--no-lever] [--seeds N]
  --out DIR        output folder (default out/resolution); renderings, sample sets and the lever's models
                   there are reused (delete DIR/models to train them again)
  --test-frames N  frames of the held-out synthetic sequence, seed 31 (default 960: 16 rooms of 60 frames)
  --model M        the model evaluated on every camera (default models/people/v2.yml, the shipped one)
  --real DIR       real 640x480 frames with boxes.csv (default ../shared/realdata/people)
  --no-real        skip the real frames (lever only)
  --no-lever       only steps 1-2: no training
  --seeds N        the lever's final models trained with training seeds 1..N (default 3): their spread shows
                   how much of a difference between the two models one training run can make
Cameras (name, size, field of view; the training mix of the lever marked *):
$(for c in "${cameras[@]}"; do IFS=: read -r n s f t m <<<"$c"; printf '  %-12s %-9s %-12s %1s %s\n' "$n" "$s" "$f" "${m:+*}" "$t"; done)
USAGE
}
# name:size:fov (rdsf-synth --fov; kinect = the Kinect v1's fx = fy = 525 px at 640x480, scaled):title:in the
# lever's training mix (1) or not (empty)
cameras=(
  "kinect1:640x480:kinect:Kinect v1 (fx 525 px, 62.7 x 49.1 degrees):1"
  "kinect1-qvga:320x240:kinect:Kinect v1 QVGA (fx 262.5 px):"
  "kinect2:512x424:70.6x60:Kinect v2 (70.6 x 60 degrees):1"
  "d435:848x480:87x58:RealSense D435 (87 x 58 degrees):1"
  "d435-hd:1280x720:87x58:RealSense D435 HD (87 x 58 degrees):"
  "orbbec:640x400:91x66:Orbbec Gemini 2 (91 x 66 degrees):1"
  # the Kinect v1's pixels (fx = fy = 525) on a frame extended down or to the sides: the field of view alone
  "taller:640x576:62.73x57.50:Kinect v1 pixels, frame extended to 57.5 degrees high:"
  "wider:880x480:79.94x49.13:Kinect v1 pixels, frame extended to 79.9 degrees wide:"
)
out=out/resolution
test_frames=960
model=models/people/v2.yml
real=../shared/realdata/people
lever=1
seeds=3
script_options resolution-report --out=out --test-frames=test_frames --model=model --real=real --no-real=real= --no-lever=lever=0 --seeds=seeds -- "$@"
case "$seeds" in ''|*[!0-9]*|0) echo "resolution-report: --seeds takes a positive number" >&2; exit 2 ;; esac
case "$test_frames" in ''|*[!0-9]*|0) echo "resolution-report: --test-frames takes a positive number of frames" >&2; exit 2 ;; esac
[ -f "$model" ] || { echo "resolution-report: $model: no such model file" >&2; exit 2; }
if [ -n "$real" ] && [ ! -f "$real/boxes.csv" ]; then
  echo "resolution-report: $real/boxes.csv not found: no real-frame evaluation (--real DIR names another folder)" >&2
  real=""
fi

started=$(date +%s)
step() { printf '\n== %s (%ds)\n' "$1" "$(( $(date +%s) - started ))" >&2; }
bin=${RDSF_BUILD_DIR:-build}
synth=$bin/synth/rdsf-synth mine=$bin/miner/rdsf-mine label=$bin/labeler/rdsf-label
train=$bin/trainer/rdsf-train detect=$bin/detector/rdsf-detect
for b in "$synth" "$mine" "$label" "$train" "$detect"; do
  [ -x "$b" ] || { echo "resolution-report: $b not built (cmake --build $bin --target $(basename "$b"))" >&2; exit 1; }
done
data=$out/data sets=$out/sets models=$out/models logs=$out/logs
run=$out/runs/$(date -u +%Y%m%dT%H%M%SZ)
mkdir -p "$data" "$sets" "$models" "$logs" "$run"
python=/usr/bin/python3

# A rendering is reused when the same generator made it with the same options (kept in DIR.options).
generator=$("$synth" --out "$out/.generator-probe" --force --frames 1 --empty >/dev/null 2>&1 &&
            grep '^generator:' "$out/.generator-probe/synth.yml"; rm -rf "$out/.generator-probe")
rendered_new=0
render() {  # name, rdsf-synth options...
  local name=$1; shift
  local options="$generator $*"
  if [ -f "$data/$name/synth.yml" ] && [ "$(cat "$data/$name.options" 2>/dev/null)" = "$options" ]; then
    echo "  $data/$name: already rendered" >&2; return
  fi
  local t0; t0=$(date +%s)
  "$synth" --out "$data/$name" --force "$@" >"$logs/render-$name.log" 2>&1 ||
    { tail -3 "$logs/render-$name.log" >&2; exit 1; }
  printf '%s\n' "$options" > "$data/$name.options"
  rendered_new=1
  echo "  $data/$name: $(tail -1 "$logs/render-$name.log" | sed 's/^rdsf-synth: //') ($(( $(date +%s) - t0 )) s)" >&2
}
camera_args() {  # size, fov
  echo "--size $1"
  [ "$2" = kinect ] || echo "--fov $2"
}

step "render the held-out sequence (seed 31, $test_frames frames) through each camera"
for c in "${cameras[@]}"; do
  IFS=: read -r name size fov _ <<<"$c"
  # shellcheck disable=SC2046
  render "test-$name" --frames "$test_frames" --people 1..4 --seed 31 --clip-frames 60 $(camera_args "$size" "$fov")
done

evaluate() {  # report folder, source, truth, models... (one rdsf-detect, every model)
  local dir=$1 source=$2 truth=$3; shift 3
  local args=() m
  for m in "$@"; do args+=(--model "$m"); done
  mkdir -p "$(dirname "$dir")"
  "$detect" --source "$source" --truth "$truth" --report-dir "$dir" --models-dir "$models" "${args[@]}" \
    --force >/dev/null 2>"$dir.log" || { cat "$dir.log" >&2; exit 1; }
}
# One row per (camera, model) of rdsf-detect's summary.md: TAR at FPPF <= 0.1 and <= 0.5 with their 95 %
# intervals, best MOTA, candidate recall, AUC.
row_header() {
  echo "| camera | size | fx, fy (px) | model | TAR at FPPF <= 0.1 (95 %) | TAR at FPPF <= 0.5 (95 %) | candidate recall | candidate AUC | best MOTA (P >=) |"
  echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"
}
rows_of() {  # summary.md, camera title, size, focal lengths
  awk -F' *\\| *' -v cam="$2" -v size="$3" -v f="$4" '
    NR > 2 && NF > 5 {
      split($11, ci, " / ")
      printf "| %s | %s | %s | %s | %s (%s) | %s (%s) | %s | %s | %s |\n", cam, size, f, $2, $3, ci[1], $4, ci[2], $7, $8, $5
    }' "$1"
}
focal_of() {  # rendering folder: "fx, fy" of its camera (synth.yml's camera line)
  sed -n 's/^camera: "[0-9x]* fx=\([0-9.]*\) fy=\([0-9.]*\).*/\1, \2/p' "$1/synth.yml"
}

# Each camera's truth restricted to the people the Kinect v1 sees: a wider camera also sees people at its
# sides (and nearer), whom the Kinect v1 never shows; they are made don't-care (visible_fraction 0: no miss,
# no false positive), so that both are judged on the same people (frame and track, >= 50 % visible in the
# Kinect v1's view; their visible share in the other view may differ).
for c in "${cameras[@]}"; do
  IFS=: read -r name _ <<<"$c"
  awk -F, -v OFS=, 'NR == FNR { if (FNR > 1 && $7 >= 0.5) seen[$1 "," $8] = 1; next }
    FNR == 1 || (($1 "," $8) in seen) { print; next } { $7 = "0.000"; print }' \
    "$data/test-kinect1/boxes.csv" "$data/test-$name/boxes.csv" > "$data/test-$name/boxes-kinect1-people.csv"
done
camera_tables() {  # run subfolder, models...: the two tables (every person; the Kinect v1's people)
  local sub=$1; shift
  local c name size fov title
  row_header >> "$report"
  for c in "${cameras[@]}"; do
    IFS=: read -r name size fov title _ <<<"$c"
    evaluate "$run/$sub/$name" "$data/test-$name" "$data/test-$name/boxes.csv" "$@"
    rows_of "$run/$sub/$name/summary.md" "$title" "$size" "$(focal_of "$data/test-$name")" >> "$report"
    echo "  $name: $(sed -n 3p "$run/$sub/$name/summary.md" | cut -c1-100)" >&2
  done
  { echo; echo "... only the people the Kinect v1 sees (the others don't-care):"; echo; row_header; } >> "$report"
  for c in "${cameras[@]}"; do
    IFS=: read -r name size fov title _ <<<"$c"
    evaluate "$run/$sub/$name-kinect1-people" "$data/test-$name" "$data/test-$name/boxes-kinect1-people.csv" "$@"
    rows_of "$run/$sub/$name-kinect1-people/summary.md" "$title" "$size" "$(focal_of "$data/test-$name")" >> "$report"
  done
  echo >> "$report"
}

step "evaluate $model on every camera"
report=$run/REPORT.md
{
  echo "# Resolution report ($(date -u +%Y-%m-%dT%H:%M:%SZ), $(nproc) cores)"
  echo
  echo "Held-out synthetic sequence: seed 31, $test_frames frames ($(( (test_frames + 59) / 60 )) rooms of 60 frames), the same"
  echo "scenes through each camera (rdsf-synth --size --fov; the Kinect v1 sensor model's noise and holes in"
  echo "every case). Model: $model. Intervals: rdsf-detect's 95 % intervals over the people."
  echo
} > "$report"
camera_tables shipped "$model"

if ((lever)); then
  step "lever: render the training recordings through the training cameras"
  rendered_new=0  # only new training recordings make the sample sets and models again
  mix=()
  for c in "${cameras[@]}"; do
    IFS=: read -r name size fov _ in_mix <<<"$c"
    [ -n "$in_mix" ] || continue
    mix+=("$name")
    # shellcheck disable=SC2046
    {
      render "train-$name" --frames 900 --people 1..4 --seed 11 --clip-frames 15 $(camera_args "$size" "$fov")
      render "empty-$name" --frames 500 --people 1..4 --seed 11 --empty --clip-frames 15 $(camera_args "$size" "$fov")
      render "empty-hard-$name" --frames 500 --people 0..0 --seed 21 --empty --clip-frames 15 $(camera_args "$size" "$fov")
    }
  done
  # The multi-camera recordings: clip c (15 frames) through camera c mod K, as list files in each camera's
  # folder (a list file's frames take the camera.yml of the list's folder).
  for kind in train empty empty-hard; do
    for k in "${!mix[@]}"; do
      (cd "$data/$kind-${mix[$k]}" && ls ./*.depth.png | sort |
         awk -v k="$k" -v n="${#mix[@]}" 'int((NR - 1) / 15) % n == k' | sed 's|^\./||') \
        > "$data/$kind-${mix[$k]}/mix.txt"
    done
  done
  if ((rendered_new)); then rm -rf "$sets"; mkdir -p "$sets"; rm -rf "${models:?}"/*; fi

  sources_of() {  # single|multi, kind: the --source arguments
    if [ "$1" = single ]; then echo "--source $data/$2-kinect1"; return; fi
    local m; for m in "${mix[@]}"; do echo "--source $data/$2-$m/mix.txt"; done
  }
  pos=1208 neg=2245
  recipe=(--group-by block --calibration platt --depth 2 --learning-rate 0.5 --augment mirror --folds 5)
  train_model() {  # name, --neg sets...
    local name=$1; shift
    if [ -f "$models/$name/v1.yml" ]; then echo "  $name: already trained" >&2; return; fi
    local t0; t0=$(date +%s)
    "$train" --models-dir "$models" --name "$name" --pos "$sets/people-$variant" --positives "$pos" \
      --negatives "$neg" --rounds 100 "${recipe[@]}" ${train_seed:+--seed "$train_seed"} --neg "$@" 2>"$logs/train-$name.log" ||
      { tail -3 "$logs/train-$name.log" >&2; exit 1; }
    grep -E "validation AUC|calibration" "$logs/train-$name.log" | sed 's/^/  /' >&2
    echo "  trained $name in $(( $(date +%s) - t0 )) s" >&2
  }
  declare -A hard
  for variant in single multi; do
    step "lever: $variant-camera sample sets"
    if [ ! -f "$sets/.done-$variant" ]; then
      rm -rf "$sets/people-$variant" "$sets/negatives-$variant"
      # shellcheck disable=SC2046
      "$mine" $(sources_of "$variant" empty) --out "$sets/negatives-$variant" 2>"$logs/mine-$variant.log" ||
        { tail -3 "$logs/mine-$variant.log" >&2; exit 1; }
      if [ "$variant" = single ]; then
        "$label" --source "$data/train-kinect1" --out "$sets/people-$variant" --truth "$data/train-kinect1/boxes.csv" \
          --answers /dev/null --keep-rejected 2>"$logs/label-$variant.log" || { tail -3 "$logs/label-$variant.log" >&2; exit 1; }
      else
        for m in "${mix[@]}"; do
          "$label" --source "$data/train-$m/mix.txt" --out "$sets/people-$variant" --truth "$data/train-$m/boxes.csv" \
            --answers /dev/null --keep-rejected 2>>"$logs/label-$variant.log" || { tail -3 "$logs/label-$variant.log" >&2; exit 1; }
        done
      fi
      touch "$sets/.done-$variant"
    fi
    grep -hE "wrote|samples|negatives|positives" "$logs/mine-$variant.log" "$logs/label-$variant.log" | tail -4 | sed 's/^/  /' >&2
  done
  # Both take as many positives as the smaller set holds (tree2's 1208 when both hold that many): a wider
  # camera shows more people, and the comparison is of cameras, not of amounts.
  labelled() { awk '/assisted:/ { for (i = 1; i < NF; ++i) if ($(i + 1) ~ /^positives/) n += $i } END { print n + 0 }' "$logs/label-$1.log"; }
  pos_single=$(labelled single) pos_multi=$(labelled multi)
  pos=$(( pos < pos_single ? pos : pos_single )); pos=$(( pos < pos_multi ? pos : pos_multi ))
  echo "  labelled positives: single $pos_single, multi $pos_multi: both models take $pos (mirrored: twice that)" >&2
  for variant in single multi; do
    step "lever: $variant-camera model"
    [ -f "$models/$variant-base/v1.yml" ] || rm -f "$sets/.hard-$variant"
    train_model "$variant-base" "$sets/negatives-$variant" "$sets/people-$variant"
    if [ ! -f "$sets/.hard-$variant" ]; then
      rm -rf "$sets/hard-$variant"
      # shellcheck disable=SC2046
      "$mine" $(sources_of "$variant" empty-hard) --out "$sets/hard-$variant" --model "$variant-base" \
        --models-dir "$models" --min-score 0 2>"$logs/mine-hard-$variant.log" ||
        { tail -3 "$logs/mine-hard-$variant.log" >&2; exit 1; }
      touch "$sets/.hard-$variant"
    fi
    hard[$variant]=$(awk '/hard negatives:/ { printf "%d (FPPF %.3f)", $4, $4 / 500 }' "$logs/mine-hard-$variant.log")
    echo "  hard negatives of $variant-base on 500 other empty frames: ${hard[$variant]}" >&2
    train_model "$variant" "$sets/negatives-$variant" "$sets/hard-$variant" "$sets/people-$variant"
    for ((s = 2; s <= seeds; ++s)); do
      train_seed=$s train_model "$variant-seed$s" "$sets/negatives-$variant" "$sets/hard-$variant" "$sets/people-$variant"
    done
  done

  step "lever: evaluate the single- and multi-camera models on every camera"
  lever_models=("$model" single multi)
  {
    echo "## The lever: trained on one camera or on several"
    echo
    echo "Two models of tree2's size ($pos positives, $neg negatives, 100 rounds; ${recipe[*]}; one round of"
    echo "hard negatives on 500 other empty frames), trained on the same scenes (seed 11, 900 frames, clips of 15):"
    echo "'single' through the Kinect v1 only, 'multi' with clip c through camera c mod ${#mix[@]} of: ${mix[*]}."
    echo "Not in the mix: the other cameras of the table. Labelled positives: single $pos_single, multi $pos_multi"
    echo "(each model takes $pos, mirrored). Hard negatives of the first round: single ${hard[single]}, multi ${hard[multi]}."
    echo
  } >> "$report"
  camera_tables lever "${lever_models[@]}"

  if [ -n "$real" ]; then
    step "lever: real frames per source and resized"
    real_abs=$(cd "$real" && pwd)
    {
      echo "Real frames ($real), per source (640x480, the Kinect v1 model):"
      echo
      row_header | sed 's/^| camera | size | fx, fy (px) |/| source | frames | camera |/'
    } >> "$report"
    for source in lab home; do
      dir=$out/real-sources/$source
      mkdir -p "$dir"
      (cd "$real_abs" && ls "$source"_*.depth.png | sed "s|^|$real_abs/|") > "$dir/frames.txt"
      awk -F, -v p="${source}_" 'NR == 1 || index($1, p) == 1' "$real/boxes.csv" > "$dir/boxes.csv"
      evaluate "$run/real/$source" "$dir/frames.txt" "$dir/boxes.csv" "${lever_models[@]}"
      rows_of "$run/real/$source/summary.md" "UC3M $source" "$(wc -l < "$dir/frames.txt")" "Kinect v1" >> "$report"
    done
    {
      echo
      echo "Real frames resized (depth by nearest neighbour, the Kinect v1 model scaled to the size: the test"
      echo "CameraFile.ResizedRealFramesWithTheirCameraModelFindTheSamePeople's measure, scripts/resized-frames.py):"
      echo "the original 640x480 frames' detections found again at IoU >= 0.7 with the box scaled, detections"
      echo "not matched, and the labelled people found (IoU >= 0.5) in the original / resized frames."
      echo
      echo "| model | size | original's detections found again | other detections | labelled people found: original / resized |"
      echo "| --- | --- | --- | --- | --- |"
    } >> "$report"
    mkdir -p "$run/resized"
    for size in 512x424 848x480 1280x720; do
      if [ ! -f "$out/resized/$size/camera.yml" ]; then
        $python scripts/resized-frames.py resize "$real" "$out/resized/$size" --size "$size" 2>"$logs/resize-$size.log" ||
          { tail -3 "$logs/resize-$size.log" >&2; exit 1; }
      fi
    done
    for m in "${lever_models[@]}"; do
      tag=$(basename "$m" .yml)
      "$detect" --source "$real" --out "$run/resized/$tag-original.csv" --model "$m" --models-dir "$models" \
        --force >/dev/null 2>"$logs/resized-$tag.log" || { cat "$logs/resized-$tag.log" >&2; exit 1; }
      for size in 512x424 848x480 1280x720; do
        "$detect" --source "$out/resized/$size" --out "$run/resized/$tag-$size.csv" --model "$m" --models-dir "$models" \
          --force >/dev/null 2>"$logs/resized-$tag.log" || { cat "$logs/resized-$tag.log" >&2; exit 1; }
        line=$($python scripts/resized-frames.py compare "$run/resized/$tag-original.csv" "$run/resized/$tag-$size.csv" \
                 --size "$size" --truth "$real/boxes.csv")
        echo "  $m at $size: $line" >&2
        read -r _ found _ people _ other _ lo lr _ total <<<"$line"
        echo "| $m | $size | $found of $people | $other | $lo / $lr of $total |" >> "$report"
      done
    done
    echo >> "$report"
  fi
fi

if ((lever)) && ((seeds > 1)); then
  step "lever: the final models of training seeds 1..$seeds"
  seed_models=(single) multi_models=(multi)
  for ((s = 2; s <= seeds; ++s)); do seed_models+=("single-seed$s"); multi_models+=("multi-seed$s"); done
  seed_models+=("${multi_models[@]}")
  {
    echo "The lever's final models trained with training seeds 1..$seeds (rdsf-train --seed; the same sample sets):"
    echo "TAR at FPPF <= 0.1 per seed and the mean, then the means at FPPF <= 0.5."
    echo
    echo "| evaluation set | single, seeds 1..$seeds | mean | multi, seeds 1..$seeds | mean | FPPF <= 0.5: single mean | multi mean |"
    echo "| --- | --- | --- | --- | --- | --- | --- |"
  } >> "$report"
  seed_row() {  # title, summary.md
    awk -F' *\\| *' -v title="$1" '
      NR > 2 && NF > 5 { v = ($2 ~ /^multi/) ? "m" : "s"; list[v] = list[v] sep[v] $3; sep[v] = ", "
                         n[v]++; a[v] += $3; b[v] += $4 }
      END { printf "| %s | %s | %.3f | %s | %.3f | %.3f | %.3f |\n", title, list["s"], a["s"] / n["s"], list["m"],
                   a["m"] / n["m"], b["s"] / n["s"], b["m"] / n["m"] }' "$2"
  }
  for c in "${cameras[@]}"; do
    IFS=: read -r name size fov title _ <<<"$c"
    evaluate "$run/seeds/$name" "$data/test-$name" "$data/test-$name/boxes.csv" "${seed_models[@]}"
    seed_row "$title $size" "$run/seeds/$name/summary.md" >> "$report"
  done
  if [ -n "$real" ]; then
    for source in lab home; do
      evaluate "$run/seeds/real-$source" "$out/real-sources/$source/frames.txt" "$out/real-sources/$source/boxes.csv" "${seed_models[@]}"
      seed_row "real, UC3M $source" "$run/seeds/real-$source/summary.md" >> "$report"
    done
  fi
  echo >> "$report"
fi

cat "$report"
echo "resolution-report: done in $(( $(date +%s) - started )) s. Report: $report" >&2
