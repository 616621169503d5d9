#!/usr/bin/env bash
# The regularisation table of issue 12: the quality report's default recipe (L5: depth-2 trees, learning rate
# 0.5, mirrored positives, 5 folds by group, Platt; tree2 size) trained with one setting changed at a time
# (bins, smoothing eps, learning rate, rounds, weight trimming, depth, seed), each model evaluated on the
# quality report's held-out synthetic sequence (16 rooms) and on the real frames. The settings are chosen
# by these held-out figures, never by the trainer's own validation.
# It reuses a quality report's recordings and sample sets (run scripts/quality-report.sh --out DIR first);
# models and reports go to DIR/sweep; the table to DIR/sweep/TABLE.md (and docs/regularisation.md with --docs).
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/lib/options.sh

usage() {
  cat <<USAGE
Usage: scripts/regularisation-sweep.sh --out DIR [--only NAME[,NAME...]] [--docs]
  --out DIR    a quality report's output folder (its data/ and sets/ are used; default out/quality)
  --only LIST  train and evaluate only these variants (names as in the table; the base is always included)
  --docs       also write the table to docs/regularisation.md (the checked-in results)
USAGE
}
out=out/quality only="" docs=0
script_options regularisation-sweep --out=out --only=only --docs=docs=1 -- "$@"
bin=${RDSF_BUILD_DIR:-build}
train=$bin/trainer/rdsf-train detect=$bin/detector/rdsf-detect
data=$out/data sets=$out/sets
test=$(cd "$data" 2>/dev/null && ls -d test-* 2>/dev/null | grep -v first240 | head -1 || true)
for need in "$sets/people" "$sets/negatives" "$sets/hard-L0" "$data/$test/boxes.csv"; do
  [ -n "$test" ] && [ -e "$need" ] || { echo "regularisation-sweep: $out has no quality report's data ($need); run scripts/quality-report.sh --out $out first" >&2; exit 1; }
done
real=../shared/realdata/people
sweep=$out/sweep models=$out/sweep/models logs=$out/sweep/logs
mkdir -p "$models" "$logs"
started=$(date +%s)

# name|options on top of the base (the quality report's L5)
variants=(
  "base|"
  "bins-16|--bins 16" "bins-32|--bins 32" "bins-128|--bins 128"
  "smooth-1e-3|--smoothing 0.001" "smooth-1e-2|--smoothing 0.01"
  "rate-0.25|--learning-rate 0.25" "rate-1|--learning-rate 1"
  "rounds-50|--rounds 50" "rounds-200|--rounds 200"
  "trim-0.05|--weight-trim 0.05" "trim-0.1|--weight-trim 0.1"
  "depth-1|--depth 1" "depth-3|--depth 3"
  "seed-2|--seed 2" "seed-3|--seed 3"
)
wanted() { [ -z "$only" ] || [ "$1" = base ] || [[ ",$only," == *",$1,"* ]]; }
names=()
for v in "${variants[@]}"; do
  name=${v%%|*} extra=${v#*|}
  wanted "$name" || continue
  names+=("$name")
  if [ -f "$models/$name/v1.yml" ]; then echo "  $name: trained already" >&2; continue; fi
  t0=$(date +%s)
  # The base's settings, the variant's option replacing the base's of the same name.
  declare -A setting=([--depth]=2 [--learning-rate]=0.5 [--augment]=mirror [--folds]=5 [--rounds]=100)
  read -r -a words <<<"$extra"
  for ((i = 0; i + 1 < ${#words[@]}; i += 2)); do setting[${words[i]}]=${words[i + 1]}; done
  options=()
  for key in "${!setting[@]}"; do options+=("$key" "${setting[$key]}"); done
  unset setting
  "$train" --models-dir "$models" --name "$name" --pos "$sets/people" --positives 1208 --negatives 2245 \
    --neg "$sets/negatives" "$sets/hard-L0" "$sets/people" --group-by block --calibration platt \
    "${options[@]}" 2>"$logs/train-$name.log" || { tail -3 "$logs/train-$name.log" >&2; exit 1; }
  echo $(( $(date +%s) - t0 )) > "$logs/train-$name.secs"
  echo "  trained $name in $(( $(date +%s) - t0 )) s ($(grep -oE 'validation AUC [0-9.]+' "$logs/train-$name.log" | tail -1))" >&2
done

args=()
for n in "${names[@]}"; do args+=(--model "$n"); done
pids=()
"$detect" --source "$data/$test" --truth "$data/$test/boxes.csv" --report-dir "$sweep/synthetic" \
  --models-dir "$models" "${args[@]}" --force >/dev/null 2>"$logs/detect-synthetic.log" & pids+=($!)
have_real=0
if [ -f "$real/boxes.csv" ]; then
  have_real=1
  "$detect" --source "$real" --truth "$real/boxes.csv" --report-dir "$sweep/real" \
    --models-dir "$models" "${args[@]}" --force >/dev/null 2>"$logs/detect-real.log" & pids+=($!)
fi
for p in "${pids[@]}"; do wait "$p" || { cat "$logs"/detect-*.log >&2; exit 1; }; done

# One row per variant: the training log's validation AUC and training time, then from each evaluation's
# summary TAR at FPPF <= 0.1 and <= 0.5, best MOTA, candidate AUC and the validation gap.
row_of() {  # summary.md, model name -> "tar01 / tar05 / mota / auc / gap"
  awk -F'|' -v m="$2 v1" '{ gsub(/^ +| +$/, "", $2) } $2 == m {
      gap = $9; sub(/.*\(/, "", gap); sub(/\).*/, "", gap); sub(/; 95 % /, " (", gap); if (gap ~ /\(/) gap = gap ")"; mota = $5; gsub(/^ +/, "", mota); sub(/ .*/, "", mota)
      gsub(/ /, "", $3); gsub(/ /, "", $4); gsub(/ /, "", $8)
      printf "%s | %s | %s | %s | %s", $3, $4, mota, $8, gap }' "$1"
}
table=$sweep/TABLE.md
{
  echo "Regularisation sweep ($(date -u +%Y-%m-%dT%H:%M:%SZ), $(nproc) cores): the quality report's L5 recipe (tree2 size,"
  echo "1208 positives asked, 2245 negatives, depth 2, rate 0.5, mirror, 5 folds by group, Platt, 64 bins, 100 rounds)"
  echo "with one setting changed. Held-out: $test (16 rooms) and the real frames; gap = held-out minus validation TAR at P >= 0.5."
  echo
  if ((have_real)); then
    echo "| variant | validation AUC | 16 rooms: TAR FPPF 0.1 | TAR FPPF 0.5 | MOTA | cand. AUC | gap | real: TAR FPPF 0.1 | TAR FPPF 0.5 | MOTA | cand. AUC | gap | s to train |"
    echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
  else
    echo "| variant | validation AUC | 16 rooms: TAR FPPF 0.1 | TAR FPPF 0.5 | MOTA | cand. AUC | gap | s to train |"
    echo "| --- | --- | --- | --- | --- | --- | --- | --- |"
  fi
  for n in "${names[@]}"; do
    auc=$(grep -oE 'validation AUC [0-9.]+' "$logs/train-$n.log" | tail -1 | awk '{ print $3 }')
    secs=$(cat "$logs/train-$n.secs" 2>/dev/null || true)
    line="| $n | ${auc:--} | $(row_of "$sweep/synthetic/summary.md" "$n")"
    ((have_real)) && line+=" | $(row_of "$sweep/real/summary.md" "$n")"
    echo "$line | ${secs:--} |"
  done
} > "$table"
cat "$table"
if ((docs)); then
  { echo "<!-- Generated by scripts/regularisation-sweep.sh --docs: do not edit by hand (docs/quality.md explains it). -->"
    echo; echo "# Regularisation sweep"; echo; cat "$table"
  } > docs/regularisation.md.tmp
  sync docs/regularisation.md.tmp && mv docs/regularisation.md.tmp docs/regularisation.md
  echo "regularisation-sweep: wrote docs/regularisation.md" >&2
fi
echo "regularisation-sweep: done in $(( $(date +%s) - started )) s. Table: $table" >&2
