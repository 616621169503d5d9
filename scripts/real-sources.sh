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

# public_source_sets OUT writes the same for the labelled public sources of datasets/public (in this
# repository, so present wherever the source tree is, with or without ../shared): public-corridor
# (pcl_people: five people in a corridor, one frame) and public-hall (tue_hero: a robot's head camera in a
# hall, five frames, seated people "don't care"), with the folder's camera.yml beside the list (a list's
# frames take the camera.yml of the list's folder). Every frame has colour; the PCL peer reads the hall (the
# corridor is PCL's own test cloud for its detector).
# No model or option here was chosen on them: unseen sources (docs/quality.md, "Public real frames").
public_source_sets() {
  local out=$1 pair name folder dir abs
  for pair in public-corridor:pcl_people public-hall:tue_hero; do
    name=${pair%%:*} folder=datasets/public/${pair#*:}
    [ -f "$folder/boxes.csv" ] || continue
    dir=$out/real-sources/$name
    mkdir -p "$dir"
    abs=$(cd "$folder" && pwd)
    (cd "$abs" && for f in *.depth.png; do echo "$abs/$f"; done) > "$dir/frames.txt"
    cp "$folder/boxes.csv" "$dir/boxes.csv"
    if [ -f "$folder/camera.yml" ]; then cp "$folder/camera.yml" "$dir/camera.yml"; else rm -f "$dir/camera.yml"; fi
    echo "$name"
  done
}
