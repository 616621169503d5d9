# Sourced (not run) by scripts/quality-report.sh and scripts/loso-report.sh: the real frames per source.
# real_source_sets REAL OUT writes OUT/real-sources/NAME/frames.txt (absolute paths of the depth frames)
# and OUT/real-sources/NAME/boxes.csv (REAL/boxes.csv's rows of those frames) for NAME = real-lab,
# real-lab-colour, real-home, real-home-colour: the frames' name prefixes lab_ (UC3M lab, lab_height
# included) and home_ (UC3M home); *-colour: the frames with a colour image (the PCL peer needs colour).
# It prints the names of the sets that hold frames, one a line (docs/quality.md, "Per source").
real_source_sets() {
  local real=$1 out=$2 real_abs source kind name dir
  real_abs=$(cd "$real" && pwd)
  for source in lab home; do
    for kind in all colour; do
      name=real-$source; [ "$kind" = colour ] && name=real-$source-colour
      dir=$out/real-sources/$name
      mkdir -p "$dir"
      (cd "$real_abs" && for f in "$source"_*.depth.png; do
         [ -f "$f" ] || continue
         [ "$kind" = colour ] && [ ! -f "${f%.depth.png}.rgb.png" ] && continue
         echo "$real_abs/$f"
       done) > "$dir/frames.txt"
      awk -F, -v p="${source}_" -v list="$dir/frames.txt" '
        BEGIN { while ((getline f < list) > 0) { sub(/.*\//, "", f); sub(/\.depth\.png$/, "", f); keep[f] = 1 } }
        NR == 1 || (index($1, p) == 1 && ($1 in keep))' "$real/boxes.csv" > "$dir/boxes.csv"
      if [ -s "$dir/frames.txt" ]; then echo "$name"; fi
    done
  done
}
