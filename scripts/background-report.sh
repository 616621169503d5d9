#!/usr/bin/env bash
# The background model's measurement (docs/quality.md, "A background model of the room"): people/v2 with
# and without rdsf-detect --background, clip by clip (a clip = one room and camera pose), each clip's
# background learned by rdsf-background from the clip's empty rendering ("empty") or from its own frames
# with people ("self", the realistic case), pooled per set by scripts/background-pool.py.
#
#   scripts/background-report.sh [--out DIR] [--sets "walls51 walls41 walls61 heldout real"] [--margin MM]
#                                 [--relative R] [--quantile Q] [--heldout DIR --heldout-empty DIR]
#
# Sets: wallsS = rdsf-synth --seed S --frames 480 --clip-frames 60 --moving-camera 0 --wall-clearance 0.25
# --people 1..4 (51 tuned the values, 61 is held out) and the same with --empty; heldout = the quality
# report's held-out rendering (seed 31, 960 frames, 16 clips), only its static clips: those whose empty
# frames lie less than 10 % in front of their own background (static synthetic rooms: 0.1-6 %, moving
# cameras: 17-58 %); real = ../shared/realdata/people's home_ and lab_height frames (one static camera
# each; the other lab recordings have 2-3 frames, too few to learn a room, and stay without a background
# in the lab's pooled row). The defaults: --out out/background, --sets as above, --margin 100,
# --relative 0.03, --quantile 0.8, the held-out rendering made under --out. Runs already made are reused.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/lib/options.sh
out=out/background sets="walls51 walls41 walls61 heldout real" margin=100 relative=0.03 quantile=0.8
heldout="" heldout_empty="" build=${RDSF_BUILD_DIR:-build}
script_options background-report --out=out --sets=sets --margin=margin --relative=relative --quantile=quantile --heldout=heldout --heldout-empty=heldout_empty -- "$@"
synth=$build/synth/rdsf-synth detect=$build/detector/rdsf-detect learn=$build/detector/rdsf-background
mkdir -p "$out/data" "$out/lists" "$out/backgrounds" "$out/runs"
out=$(cd "$out" && pwd)
tag="m${margin}-r${relative}-q${quantile}"

render() {  # NAME SEED [--empty]
  local name=$1 seed=$2; shift 2
  [ -f "$out/data/$name/boxes.csv" ] && return
  "$synth" --out "$out/data/$name" --frames 480 --clip-frames 60 --seed "$seed" --moving-camera 0 \
    --wall-clearance 0.25 --people 1..4 --force "$@" 2>/dev/null
}

clip_list() {  # FOLDER CLIP -> a list file of the clip's 60 frames
  local folder=$1 clip=$2 list i
  list=$out/lists/$(echo "$folder" | tr '/' '_').clip$clip.txt
  if [ ! -s "$list" ]; then
    for i in $(seq $((clip * 60)) $((clip * 60 + 59))); do printf '%s/%06d.depth.png\n' "$folder" "$i"; done > "$list"
  fi
  echo "$list"
}

background() {  # LIST NAME -> the folder of LIST's background (learned once per quantile)
  local dir=$out/backgrounds/$2.q$quantile
  [ -f "$dir/camera.yml" ] || "$learn" --source "$1" --out "$dir" --quantile "$quantile" --force 2> "$dir.err" || {
    cat "$dir.err" >&2; exit 1; }
  echo "$dir"
}

part() {  # RUN LIST BOXES [BACKGROUND]: one rdsf-detect evaluation into $out/runs/RUN
  local dir=$out/runs/$1 list=$2 boxes=$3 bg=${4:-}
  [ -f "$dir/report/curve.csv" ] && return
  mkdir -p "$dir"
  local extra=()
  [ -n "$bg" ] && extra=(--background "$bg" --background-margin "$margin" --background-relative "$relative")
  "$detect" --source "$list" --truth "$boxes" --model people --report-dir "$dir/report" --force --threads 2 \
    "${extra[@]}" > /dev/null 2> "$dir/detect.err" || { tail -3 "$dir/detect.err" >&2; exit 1; }
}

static_clip() {  # BACKGROUND_ERR: true when the clip's empty frames lie < 10 % in front of their background
  awk '/lie in front/ { for (i = 1; i <= NF; ++i) if ($(i + 1) == "%") { exit !($i < 10.0) } }' "$1"
}

pool() { python3 scripts/background-pool.py "$@"; }

synthetic_set() {  # SET FOLDER EMPTY_FOLDER CLIPS
  local set=$1 folder=$2 empty=$3 clips=$4 clip list elist ebg sbg
  local off=() on_empty=() on_self=()
  for clip in $(seq 0 $((clips - 1))); do
    list=$(clip_list "$folder" "$clip"); elist=$(clip_list "$empty" "$clip")
    ebg=$(background "$elist" "$set-empty.clip$clip")
    if [ "$set" = heldout ] && ! static_clip "$ebg.err"; then continue; fi
    sbg=$(background "$list" "$set.clip$clip")
    part "$set/clip$clip/off" "$list" "$folder/boxes.csv"
    part "$set/clip$clip/empty-$tag" "$list" "$folder/boxes.csv" "$ebg"
    part "$set/clip$clip/self-$tag" "$list" "$folder/boxes.csv" "$sbg"
    off+=("$out/runs/$set/clip$clip/off"); on_empty+=("$out/runs/$set/clip$clip/empty-$tag")
    on_self+=("$out/runs/$set/clip$clip/self-$tag")
  done
  echo "$set: ${#off[@]} static clips"
  pool "$set off" "${off[@]}"
  pool "$set background of the empty room" "${on_empty[@]}"
  pool "$set background of its own frames" "${on_self[@]}"
}

real_set() {
  local real list bg
  real=$(cd ../shared/realdata/people && pwd)
  for prefix in home_ lab_height; do
    list=$out/lists/real-$prefix.txt
    ls "$real"/$prefix*.depth.png > "$list"
    bg=$(background "$list" "real-$prefix")
    part "real/$prefix/off" "$list" "$real/boxes.csv"
    part "real/$prefix/self-$tag" "$list" "$real/boxes.csv" "$bg"
  done
  list=$out/lists/real-lab-other.txt
  ls "$real"/lab_*.depth.png | grep -v lab_height > "$list"
  part "real/lab-other/off" "$list" "$real/boxes.csv"
  pool "UC3M home off" "$out/runs/real/home_/off"
  pool "UC3M home background of its own frames" "$out/runs/real/home_/self-$tag"
  pool "UC3M lab_height off" "$out/runs/real/lab_height/off"
  pool "UC3M lab_height background of its own frames" "$out/runs/real/lab_height/self-$tag"
  pool "UC3M lab off" "$out/runs/real/lab_height/off" "$out/runs/real/lab-other/off"
  pool "UC3M lab, lab_height with its background" "$out/runs/real/lab_height/self-$tag" "$out/runs/real/lab-other/off"
}

echo "background-report: margin $margin mm, relative $relative, quantile $quantile"
echo "set | frames | people | candidate recall | TAR at FPPF <= 0.1 | TAR at FPPF <= 0.5 | candidates | time"
for set in $sets; do
  case $set in
    walls*)
      seed=${set#walls}
      render "$set" "$seed"; render "$set-empty" "$seed" --empty
      synthetic_set "$set" "$out/data/$set" "$out/data/$set-empty" 8 ;;
    heldout)
      if [ -z "$heldout" ]; then
        heldout=$out/data/heldout heldout_empty=$out/data/heldout-empty
        for e in "" --empty; do
          d=$heldout; [ -n "$e" ] && d=$heldout_empty
          [ -f "$d/boxes.csv" ] || "$synth" --out "$d" --frames 960 --clip-frames 60 --people 1..4 --seed 31 --force $e 2>/dev/null
        done
      fi
      synthetic_set heldout "$(cd "$heldout" && pwd)" "$(cd "$heldout_empty" && pwd)" 16 ;;
    real) real_set ;;
    *) echo "background-report: unknown set '$set'" >&2; exit 2 ;;
  esac
done
