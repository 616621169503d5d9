#!/usr/bin/env bash
# The adaptation benchmark (issue 35): how many answers a room costs and what its detector reaches, with
# the truth as the person (every answer it gives is counted). For every room, its frames are split in time:
# the earlier part is adapted on, the later part evaluated (TAR at FPPF <= 0.1, rdsf-detect's exact curve):
#   none            the base model (--people-version: people/v2 by default, the model of the tables in
#                   docs/adapting-to-your-room.md; 4 for today's default people/v4)
#   negatives       continued (--init) 10 rounds on the room's negatives and the synthetic base (rdsf-adapt's
#                   default until 2026-12-07, kept so that the tables of this row compare)
#   per candidate   rdsf-adapt --per-candidate --budget B (every candidate the model is unsure of is asked)
#   per track       rdsf-adapt --budget B (one answer per track), continuing the base model (rdsf-adapt's
#                   default rounds: 3, 10 until 2026-12-07; its held-out check on, --holdout-check auto with this
#                   small base, since 2026-12-07: --adapt-args "--holdout-check off" for the rows before)
#   retrain         per track at the largest budget, trained from nothing (100 rounds) instead
# A synthetic room whose later half has no counted person (all out of view or less than half visible) has no
# TAR: it is left out and the next room taken, so --synthetic N rooms are evaluated.
# Rooms: the real ones in ../shared/realdata/people (lab: 24 frames in name order, 12 + 12, its two empty
# frames as --empty; home: 22 frames, 11 + 11, no empty recording) and the first --synthetic N of the 16
# held-out synthetic rooms of the quality report (seed 31, 60 frames each: 30 + 30, the same rooms rendered
# empty as --empty). The base: rdsf-adapt's own small base (600 frames of seed 11 and 300 empty, its people
# labelled from the truth and its empty frames mined, cut as --base-cut says: by default with the detector's
# default options), far smaller than the shipped model's 18,000 frames; rendered once into OUT/base-cache
# (rdsf-adapt --base-cache), its sets once per set of analyser options, so that every room is adapted as
# rdsf-adapt adapts by default (until 2026-12-08 the benchmark rendered a base of its own; the base's furniture has
# no dropout holes, as people/v3's and v4's training, also with --people-version 2, whose training had them).
# --camera 'OPTIONS' renders the held-out rooms through another camera (rdsf-synth's --size and --fov, e.g.
# a Kinect v2's 512x424 at 70.6 x 60 degrees; the base stays Kinect v1, as the shipped model's training).
# --people-distance MIN..MAX renders the held-out rooms with their people that far from the camera (rdsf-synth's
# option, in metres; e.g. 0.8..2.5: issue 34's office, people passing close to a camera at chest height).
# --base DIR takes the base from a folder of sample sets instead (DIR/people and DIR/negatives, e.g. the sets
# scripts/train-default-model.sh makes for the shipped model: the default model's size, its positives from
# people/ and its negatives from both, as that script trains); --modes picks rows.
# Writes out/adaptation/REPORT.md (a table, the same in people found: scripts/adaptation-compare.py, which also
# compares two runs) and curve.png (answers against TAR); rerunning reuses the
# recordings and sets, and each rdsf-adapt run resumes.
# The whole script is one block, read before any of it runs: a run takes many minutes, and bash reads a plain
# script as it goes, so editing this file during a run would change what the run does next.
{
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/lib/options.sh

usage() {
  cat <<USAGE
Usage: scripts/adaptation-benchmark.sh [--out DIR] [--synthetic N] [--budgets "B ..."] [--real DIR] [--base DIR]
                                      [--modes "M ..."] [--camera 'OPTIONS'] [--people-distance MIN..MAX]
                                      [--people-version N] [--seed N]
  --out DIR        work folder (default out/adaptation)
  --synthetic N    synthetic held-out rooms to use, 0-16 (default 4)
  --budgets "..."  answer budgets of the per-candidate and per-track runs (default "10 50")
  --real DIR       real frames with boxes.csv (default ../shared/realdata/people; its ../empty for the lab)
  --base DIR       the synthetic base's sample sets DIR/people and DIR/negatives (default: rdsf-adapt's own small
                   base, seed 11, 600 frames and 300 empty, kept in OUT/base-cache)
  --modes "..."    rows to run besides "none", of: track candidate retrain negatives (default all four)
  --adapt-args ".." more options for every rdsf-adapt run, e.g. "--propagate-model-answers on" (default none)
  --camera '...'   rdsf-synth options of the camera the synthetic held-out rooms are seen by, e.g.
                   '--size 512x424 --fov 70.6x60' (a Kinect v2); the base stays Kinect v1 (default none: Kinect v1)
  --people-distance MIN..MAX  the synthetic held-out rooms' people this far from the camera, in metres
                   (rdsf-synth's option; e.g. 0.8..2.5, people passing close to the camera; default: the rooms'
                   own spread)
  --people-version N  the shipped people/vN every room starts from and is judged against (default 2: the
                   tables' model; 4: today's default); one version per work folder
  --seed N         rdsf-synth's seed of the 16 synthetic held-out rooms (default 31: the quality report's;
                   another renders other rooms, e.g. to check a choice made on these)
USAGE
}
out=out/adaptation synthetic=4 budgets="10 50" real=../shared/realdata/people base="" modes="track candidate retrain negatives"
adapt_args_text="" camera_text="" people_distance="" people_version=2 seed=31
script_options adaptation-benchmark --out=out --synthetic=synthetic --budgets=budgets --real=real --base=base --modes=modes --adapt-args=adapt_args_text --camera=camera_text --people-distance=people_distance --people-version=people_version --seed=seed -- "$@"
case "$seed" in ''|*[!0-9]*) echo "adaptation-benchmark: --seed takes a whole number" >&2; exit 2 ;; esac
[ -f "models/people/v$people_version.yml" ] || { echo "adaptation-benchmark: --people-version: no models/people/v$people_version.yml" >&2; exit 2; }
read -r -a adapt_args <<<"$adapt_args_text"
read -r -a camera <<<"$camera_text"
for c in "${camera[@]}"; do
  case "$c" in --size|--fov|[0-9]*x[0-9]*|kinect) ;; *) echo "adaptation-benchmark: --camera takes rdsf-synth's --size WxH and --fov HxV, not '$c'" >&2; exit 2 ;; esac
done
distance=()
if [ -n "$people_distance" ]; then
  [[ "$people_distance" =~ ^[0-9.]+\.\.[0-9.]+$ ]] ||
    { echo "adaptation-benchmark: --people-distance takes MIN..MAX in metres, e.g. 0.8..2.5, not '$people_distance'" >&2; exit 2; }
  distance=(--people-distance "$people_distance")
fi
# The held-out rooms of another camera or people distance are rendered into folders of their own.
heldout=heldout
[ "$seed" = 31 ] || heldout=heldout-seed$seed
[ -z "$camera_text" ] || heldout=$heldout-$(echo "${camera[*]}" | md5sum | cut -c1-8)
[ -z "$people_distance" ] || heldout=$heldout-near$people_distance
case "$synthetic" in ''|*[!0-9]*) echo "adaptation-benchmark: --synthetic takes 0-16" >&2; exit 2 ;; esac
((synthetic <= 16)) || { echo "adaptation-benchmark: --synthetic takes 0-16" >&2; exit 2; }
for m in $modes; do
  case "$m" in track|candidate|retrain|negatives) ;; *) echo "adaptation-benchmark: --modes: unknown mode '$m'" >&2; exit 2 ;; esac
done
wants() { [[ " $modes " == *" $1 "* ]]; }
if [ -n "$base" ]; then
  for s in people negatives; do
    [ -f "$base/$s/manifest.yml" ] || { echo "adaptation-benchmark: --base $base: no sample set $s/ there" >&2; exit 2; }
  done
fi

bin=${RDSF_BUILD_DIR:-build}
synth=$bin/synth/rdsf-synth train=$bin/trainer/rdsf-train detect=$bin/detector/rdsf-detect adapt=$bin/adapt/rdsf-adapt
data=$out/data models=$out/models rooms=$out/rooms
mkdir -p "$data" "$models" "$rooms"
threads=2
step() { printf '\n== %s\n' "$1" >&2; }

step "the held-out rooms (reused when present)"
# With --base, the negatives are both sets' (the people set's candidates that are nobody included), as
# scripts/train-default-model.sh trains the shipped model; rdsf-adapt's small base gives its mined negatives only.
base_args=(--base-cache "$out/base-cache")
if [ -n "$base" ]; then
  base_pos=$base/people base_neg=("$base/negatives" "$base/people")
  base_args=(--base-pos "$base_pos" --base-neg "${base_neg[@]}")
fi
if ((synthetic > 0)); then
  [ -f "$data/$heldout/synth.yml" ] ||
    "$synth" --out "$data/$heldout" --force --frames 960 --people 1..4 --seed "$seed" --clip-frames 60 "${camera[@]}" \
      "${distance[@]}" >/dev/null 2>&1
  [ -f "$data/$heldout-empty/synth.yml" ] ||
    "$synth" --out "$data/$heldout-empty" --force --frames 960 --people 1..4 --seed "$seed" --empty --clip-frames 60 \
      "${camera[@]}" "${distance[@]}" >/dev/null 2>&1
fi

# A room: NAME, then files adapt.txt, eval.txt, truth.csv and optionally empty.txt in $rooms/NAME.
list() {  # folder, frame names... -> absolute paths, one a line
  local dir; dir=$(cd "$1" && pwd); shift
  for f in "$@"; do echo "$dir/$f.depth.png"; done
}
truth_of() {  # boxes.csv, frame names... -> their rows
  local csv=$1; shift
  head -1 "$csv"
  printf '%s\n' "$@" | awk -F, 'NR == FNR { keep[$1] = 1; next } FNR > 1 && ($1 in keep)' - "$csv"
}
room_names=()
make_room() {  # name, source folder, boxes.csv, split index, frame names...
  local name=$1 folder=$2 csv=$3 split=$4; shift 4
  local all=("$@") w=$rooms/$name
  mkdir -p "$w"
  list "$folder" "${all[@]:0:split}" > "$w/adapt.txt"
  list "$folder" "${all[@]:split}" > "$w/eval.txt"
  truth_of "$csv" "${all[@]}" > "$w/truth.csv"
  # A list file's frames take the camera.yml of the list's folder (docs/sensors.md): the room's own camera.
  if [ -f "$folder/camera.yml" ]; then cp "$folder/camera.yml" "$w/camera.yml"; else rm -f "$w/camera.yml"; fi
  room_names+=("$name")
}
if [ -f "$real/boxes.csv" ]; then
  mapfile -t lab < <(cd "$real" && ls lab_*.depth.png | sed 's/\.depth\.png$//' | sort)
  make_room lab "$real" "$real/boxes.csv" $(( ${#lab[@]} / 2 )) "${lab[@]}"
  if [ -f "$real/../empty/lab_empty_lab.depth.png" ]; then
    list "$real/../empty" lab_empty_lab lab_inside1 > "$rooms/lab/empty.txt"
  fi
  mapfile -t home < <(cd "$real" && ls home_*.depth.png | sed 's/\.depth\.png$//' | sort)
  make_room home "$real" "$real/boxes.csv" $(( ${#home[@]} / 2 )) "${home[@]}"
else
  echo "adaptation-benchmark: $real/boxes.csv not found: real rooms skipped" >&2
fi
taken=0
for ((r = 0; r < 16 && taken < synthetic; ++r)); do
  names=()
  for ((f = r * 60; f < r * 60 + 60; ++f)); do names+=("$(printf '%06d' "$f")"); done
  counted=$(printf '%s\n' "${names[@]:30}" |
            awk -F, 'NR == FNR { keep[$1] = 1; next } FNR > 1 && ($1 in keep) && $7 >= 0.5' - "$data/$heldout/boxes.csv" | wc -l)
  if ((counted == 0)); then echo "adaptation-benchmark: synthetic room $((r + 1)): nobody counted in its later half, left out" >&2; continue; fi
  make_room "synthetic-$((r + 1))" "$data/$heldout" "$data/$heldout/boxes.csv" 30 "${names[@]}"
  list "$data/$heldout-empty" "${names[@]:0:30}" > "$rooms/synthetic-$((r + 1))/empty.txt"
  taken=$((taken + 1))
done

tar_of() {  # model, room -> TAR at FPPF <= 0.1 on the room's later frames
  local report=$rooms/$2/report-$(echo "$1" | tr '/' '-')
  "$detect" --source "$rooms/$2/eval.txt" --truth "$rooms/$2/truth.csv" --model "$1" --models-dir "$models" \
    --report-dir "$report" --force >/dev/null 2>&1
  sed -n 's/.*exact curve: TAR \([0-9.]*\) at FPPF <= 0.1.*/\1/p' "$report/summary.txt"
}
field() { awk -F'\t' -v k="$2" '$1 == k { print $2 }' "$1"; }
# The base model alone in the work folder's people/: 'people' (rdsf-adapt's default, --init people) is it.
for other in "$models"/people/v*.yml; do
  [ -e "$other" ] && [ "$other" != "$models/people/v$people_version.yml" ] &&
    { echo "adaptation-benchmark: $out holds $other, another base than people/v$people_version: use another --out" >&2; exit 1; }
done
[ -f "$models/people/v$people_version.yml" ] ||
  { mkdir -p "$models/people"; cp "models/people/v$people_version.yml" "$models/people/v$people_version.yml"; }

results=$out/results.tsv
printf 'room\tmode\tbudget\tanswers\tpropagated\tpropagated_wrong\ttar\ttrain_s\n' > "$results"
for room in "${room_names[@]}"; do
  w=$rooms/$room
  step "room $room: $(wc -l < "$w/adapt.txt") frames to adapt on, $(wc -l < "$w/eval.txt") to evaluate"
  empty=()
  # The benchmark's empty recordings are known to be empty (rendered without people; the lab's empty frames):
  # where the model follows a false positive over 5 frames there, rdsf-adapt is told so (--trust-empty).
  [ -f "$w/empty.txt" ] && empty=(--empty "$w/empty.txt" --trust-empty)
  before=$(tar_of people "$room")
  printf '%s\tnone\t0\t0\t0\t0\t%s\t0\n' "$room" "$before" >> "$results"
  for budget in $budgets; do
    for mode in track candidate; do
      wants "$mode" || continue
      run=$w/$mode-$budget
      flags=()
      [ "$mode" = candidate ] && flags=(--per-candidate)
      "$adapt" --source "$w/adapt.txt" "${empty[@]}" --truth "$w/truth.csv" --eval "$w/eval.txt" --out "$run" \
        --name "$room-$mode-$budget" --models-dir "$models" --budget "$budget" --threads $threads \
        "${base_args[@]}" "${flags[@]}" "${adapt_args[@]}" 2>"$run.log" ||
        { tail -3 "$run.log" >&2; exit 1; }
      state=$run/adapt-state.tsv
      # propagated: along the people's tracks and places, and along the model's sure answers' tracks; wrong: the
      # truth's count on the people's tracks' line (the per place line is a part of it) and the model's tracks' line
      wrong=$(sed -n 's/^rdsf-label: \(per track\|model answers. tracks\): .*the truth contradicts \([0-9]*\) .*/\2/p' \
        "$run/logs/answers.log" | awk '{ n += $1 } END { print n + 0 }')
      propagated=$(( $(field "$state" answers.propagated) + $(field "$state" answers.model_track) ))
      printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$room" "$mode" "$budget" "$(field "$state" answers.human)" \
        "$propagated" "$wrong" "$(field "$state" tar_after)" \
        "$(field "$state" train_seconds)" >> "$results"
      echo "$room $mode $budget: $(tail -1 "$results" | cut -f4-8)" >&2
    done
  done
  # Retrained from nothing (100 rounds) on the per-track answers of the largest budget, to compare.
  if wants retrain; then
    budget=${budgets##* } run=$w/retrain-${budgets##* }
    "$adapt" --source "$w/adapt.txt" "${empty[@]}" --truth "$w/truth.csv" --eval "$w/eval.txt" --out "$run" \
      --name "$room-retrain-$budget" --models-dir "$models" --budget "$budget" --threads $threads --retrain \
      "${base_args[@]}" "${adapt_args[@]}" 2>"$run.log" || { tail -3 "$run.log" >&2; exit 1; }
    state=$run/adapt-state.tsv
    printf '%s\tretrain\t%s\t%s\t%s\t0\t%s\t%s\n' "$room" "$budget" "$(field "$state" answers.human)" \
      "$(( $(field "$state" answers.propagated) + $(field "$state" answers.model_track) ))" "$(field "$state" tar_after)" \
      "$(field "$state" train_seconds)" >> "$results"
  fi
  # Negatives only: the same training on the room's negatives (mined by the per-track run) and the base (without
  # --base: the one the per-track run trained with).
  wants negatives || continue
  negatives=$w/track-${budgets%% *}/sets/room-negatives
  if [ -f "$negatives/manifest.yml" ]; then
    [ -n "$base" ] || { state=$w/track-${budgets%% *}/adapt-state.tsv;
      base_pos=$(field "$state" base.people) base_neg=("$(field "$state" base.negatives)"); }
    start=$(date +%s.%N)
    "$train" --models-dir "$models" --name "$room-negatives" --init people --rounds 10 --folds 0 \
      --pos "$base_pos" --neg "$negatives" "${base_neg[@]}" >/dev/null 2>"$w/negatives-train.log"
    seconds=$(echo "$(date +%s.%N) - $start" | bc)
    printf '%s\tnegatives\t0\t0\t0\t0\t%s\t%.1f\n' "$room" "$(tar_of "$room-negatives" "$room")" "$seconds" >> "$results"
  else
    printf '%s\tnegatives\t0\t0\t0\t0\t%s\t0\n' "$room" "$before" >> "$results"  # no empty frames: as before
  fi
done

step "report"
"$adapt" --chart "$results" --chart-png "$out/curve.png" >/dev/null
{
  echo "# Adaptation benchmark ($(date -u +%Y-%m-%dT%H:%MZ))"
  echo
  echo "TAR at FPPF <= 0.1 on each room's later frames; answers = the truth-as-person's answers (rdsf-adapt"
  echo "--truth); propagated = labels written along tracks, the person's and the model's sure answers' (wrong:"
  echo "contradicted by the truth); train s = rdsf-train"
  echo "wall time (from the last answer to the model)."
  [ -z "$camera_text" ] || echo "The synthetic rooms are seen through rdsf-synth $camera_text (the base: Kinect v1)."
  [ -z "$people_distance" ] || echo "The synthetic rooms' people stand $people_distance m from the camera (rdsf-synth --people-distance)."
  echo
  echo "| room | mode | budget | answers | propagated (wrong) | TAR | train s |"
  echo "| --- | --- | --- | --- | --- | --- | --- |"
  awk -F'\t' 'NR > 1 { printf "| %s | %s | %s | %s | %s (%s) | %s | %s |\n", $1, $2, $3, $4, $5, $6, $7, $8 }' "$results"
  echo
  echo "![answers against TAR](curve.png)"
  echo
  scripts/adaptation-compare.py "$out"
} > "$out/REPORT.md"
cat "$out/REPORT.md"
exit
}
