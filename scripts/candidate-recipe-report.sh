#!/usr/bin/env bash
# A default model's recipe retrained on candidates made with other options, against the shipped model of that
# version (docs/quality.md, "A people version trained with the two rules", with people/v2):
#
#   scripts/candidate-recipe-report.sh [--out DIR] [--recipes 'NAME=OPTIONS;...'] [--seeds "1 2"]
#                                      [--sets "lab home seed31 ..."] [--data DIR] [--real DIR] [--shipped-only]
#                                      [--people-version 2|3|4]
#
# --people-version N (default 2, the version the documented tables were made with): the recipe
# scripts/train-default-model.sh --people-version N trains, and the shipped people/vN it is compared with. From
# 2026-12-06, when train-default-model.sh's default version became 3 (then 4), until 2026-12-07 this script
# read people/v2.yml beside the model trained (the shipped file, copied there as an earlier version), so its
# "trained" rows were people/v2's; it now names the version for both.
#
# For each recipe NAME=OPTIONS (rdsf-detect's candidate options; empty: the defaults, people/vN's own recipe),
# scripts/train-default-model.sh --candidates OPTIONS mines and labels the shipped recipe's rendered frames
# with them and trains with the first seed; each other seed retrains the same sets (train-default-model.sh
# --sets-from --seed: another feature pool and other folds, the recipe's spread). The frames are rendered once
# under --out, or taken from --data DIR (a train-default-model work folder's data/, e.g.
# out/default-model/a/data). Every model is evaluated with its own options, and the shipped people/vN with
# each recipe's options, by rdsf-detect --truth on each set (TAR at FPPF <= 0.1 with its 95 % interval, at
# FPPF <= 0.5, candidate AUC, people without a candidate):
#   lab, home    ../shared/realdata/people's UC3M sources (scripts/real-sources.sh; skipped without --real)
#   seedS        rdsf-synth --frames 960 --people 1..4 --clip-frames 60 --seed S (seed31: the quality report's)
#   wallsS       the same, --frames 480 --moving-camera 0 --wall-clearance 0.25 (people against walls)
#   closeS       the same, --frames 480 --people-distance 0.8..2.5 (people the image cuts)
# Defaults: --out out/candidate-recipes, --recipes 'v2=;v3b=--border-height 25;v3bf=--border-height 25
# --local-front 70', --seeds "1 2", --sets "lab home seed31 seed81 seed91 seed37 walls71 close72 close74",
# --real ../shared/realdata/people. Runs already made are reused. About 20 minutes of rendering (none with
# --data), 9 minutes a recipe and 5 an extra seed on 2 cores, and 10-40 s a set and model.
# --shipped-only trains nothing: people/vN with each recipe's options on every set (a candidate option judged
# on several renderings and both real sources in minutes; docs/quality.md, "The 16 rooms of seed 31 as the
# judge": --recipes 'off=;narrow=--narrow-fitted-width 20'). Writes DIR/table.md and prints it.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/lib/options.sh
. scripts/real-sources.sh
out=out/candidate-recipes recipes='v2=;v3b=--border-height 25;v3bf=--border-height 25 --local-front 70'
seeds="1 2" sets="lab home seed31 seed81 seed91 seed37 walls71 close72 close74" data="" real=../shared/realdata/people
shipped_only=0 people_version=2
script_options candidate-recipe-report --out=out --recipes=recipes --seeds=seeds --sets=sets --data=data \
  --real=real --shipped-only=shipped_only=1 --people-version=people_version -- "$@"
case "$people_version" in 2|3|4) ;; *) echo "candidate-recipe-report: --people-version takes 2, 3 or 4" >&2; exit 2 ;; esac
[[ "$seeds" =~ ^[0-9]+( [0-9]+)*$ ]] || { echo "candidate-recipe-report: --seeds takes numbers" >&2; exit 2; }
for set in $sets; do
  [[ "$set" =~ ^(lab|home|seed[0-9]+|walls[0-9]+|close[0-9]+)$ ]] ||
    { echo "candidate-recipe-report: unknown set '$set'" >&2; exit 2; }
done
IFS=';' read -r -a recipe_list <<<"$recipes"
for r in "${recipe_list[@]}"; do
  [[ "$r" =~ ^[A-Za-z0-9_-]+= ]] || { echo "candidate-recipe-report: a recipe is NAME=OPTIONS, not '$r'" >&2; exit 2; }
done
if [ -n "$data" ] && ! [ -f "$data/train/synth.yml" -a -f "$data/empty/synth.yml" ]; then
  echo "candidate-recipe-report: $data holds no train/ and empty/ renderings (--data)" >&2
  exit 1
fi
bin=${RDSF_BUILD_DIR:-build}
mkdir -p "$out/models" "$out/runs" "$out/sets-data"
out=$(cd "$out" && pwd)
if [ -z "$data" ]; then data=$out/rendering; mkdir -p "$data"; fi
data=$(cd "$(dirname "$data")" && pwd)/$(basename "$data")
if ((shipped_only)); then seeds=""; fi

# The models: $out/models/NAME-sSEED.yml (none with --shipped-only).
first_seed=${seeds%% *}
for r in "${recipe_list[@]}"; do
  [ -n "$seeds" ] || break
  name=${r%%=*} options=${r#*=}
  work=$out/train/$name
  mkdir -p "$work/a"
  [ -e "$work/a/data" ] || ln -s "$data" "$work/a/data"
  if [ ! -f "$out/models/$name-s$first_seed.yml" ]; then
    scripts/train-default-model.sh --out "$work" --candidates "$options" --seed "$first_seed" \
      --people-version "$people_version" > "$work.log" 2>&1 || { tail -3 "$work.log" >&2; exit 1; }
    cp "$work/a/models/people/v$people_version.yml" "$out/models/$name-s$first_seed.yml"
  fi
  for seed in $seeds; do
    [ -f "$out/models/$name-s$seed.yml" ] && continue
    scripts/train-default-model.sh --out "$work-s$seed" --sets-from "$work/a" --seed "$seed" \
      --people-version "$people_version" > "$work-s$seed.log" 2>&1 || { tail -3 "$work-s$seed.log" >&2; exit 1; }
    cp "$work-s$seed/a/models/people/v$people_version.yml" "$out/models/$name-s$seed.yml"
  done
done

set_source() {  # SET -> "SOURCE BOXES" (rendered when missing)
  local set=$1 dir seed
  case $set in
    lab|home)
      dir=$out/sets-data/real-sources/real-$set
      [ -f "$dir/frames.txt" ] || real_source_sets "$real" "$out/sets-data" > /dev/null
      echo "$dir/frames.txt $dir/boxes.csv"; return ;;
    seed*) seed=${set#seed} ;;
    walls*) seed=${set#walls} ;;
    close*) seed=${set#close} ;;
  esac
  dir=$out/sets-data/$set
  if [ ! -f "$dir/boxes.csv" ]; then
    case $set in
      seed*) "$bin/synth/rdsf-synth" --out "$dir" --force --frames 960 --people 1..4 --clip-frames 60 --seed "$seed" ;;
      walls*) "$bin/synth/rdsf-synth" --out "$dir" --force --frames 480 --people 1..4 --clip-frames 60 --seed "$seed" \
                --moving-camera 0 --wall-clearance 0.25 ;;
      close*) "$bin/synth/rdsf-synth" --out "$dir" --force --frames 480 --people 1..4 --clip-frames 60 --seed "$seed" \
                --people-distance 0.8..2.5 ;;
    esac > /dev/null 2> "$dir.err" || { tail -3 "$dir.err" >&2; exit 1; }
  fi
  echo "$dir $dir/boxes.csv"
}

row() {  # LABEL MODEL OPTIONS SET: one evaluation, printed as a table row
  local label=$1 model=$2 options=$3 set=$4 run found source boxes log curve people missing auc
  if [[ "$set" =~ ^(lab|home)$ ]] && [ ! -f "$real/boxes.csv" ]; then return; fi
  found=$(set_source "$set") || exit 1
  read -r source boxes <<<"$found"
  run=$out/runs/$label/$set
  log=$run/detect.log
  if [ ! -f "$run/report/summary.txt" ]; then
    mkdir -p "$run"
    read -r -a extra <<<"$options"
    "$bin/detector/rdsf-detect" --source "$source" --model "$model" --truth "$boxes" --report-dir "$run/report" \
      --force --threads 2 "${extra[@]}" > "$log" 2>&1 || { tail -3 "$log" >&2; exit 1; }
  fi
  curve=$(grep -o 'TAR [0-9.]* at FPPF <= 0.1, [0-9.]* at FPPF <= 0.5 (95 % intervals over the [0-9]* people: [0-9.]*-[0-9.]*' "$log" | head -1)
  people=$(sed -E 's/.* over the ([0-9]+) people.*/\1/' <<<"$curve")
  missing=$(grep -oE '[0-9]+ segmentation errors' "$run/report/summary.txt" | head -1 | cut -d' ' -f1)
  auc=$(grep -oE 'AUC [0-9.]+' "$log" | head -1 | cut -d' ' -f2)
  awk -v l="$label" -v o="${options:-defaults}" -v s="$set" -v p="$people" -v m="$missing" -v a="$auc" -v c="$curve" 'BEGIN {
    split(c, w, " "); iv = w[length(w)]
    printf "| %s | %s | %s | %s | %s | %s (%s) | %s | %s |\n", l, o, s, p, m, w[2], iv, w[7], a }'
}

{
  echo "| model | candidate options | set | people | no candidate | TAR at FPPF <= 0.1 (95 %) | TAR at FPPF <= 0.5 | candidate AUC |"
  echo "| --- | --- | --- | --- | --- | --- | --- | --- |"
  for r in "${recipe_list[@]}"; do
    name=${r%%=*} options=${r#*=}
    for set in $sets; do
      row "people-v$people_version+$name" "people/v$people_version" "$options" "$set"
      for seed in $seeds; do row "$name-s$seed" "$out/models/$name-s$seed.yml" "$options" "$set"; done
    done
  done
} > "$out/table.md.tmp"
mv "$out/table.md.tmp" "$out/table.md"
cat "$out/table.md"
