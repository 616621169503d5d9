#!/usr/bin/env bash
# Checks that every #include points the way docs/architecture.md says: a library folder includes only the
# folders to its left in the flow (and itself), the library never includes a program, cli/ or gui/ (nor
# Boost.ProgramOptions or highgui, nor OpenCV's imgcodecs outside frame/image_codecs_module.cpp), and a
# program folder includes the library, cli/, gui/ and itself, never another program. Prints one line per
# wrong include and exits 1 when there is one (CTest: include_direction).
set -euo pipefail
cd "$(dirname "$0")/.."

# The library's folders in the order of the flow; each may include the ones before it.
flow="core frame segmentation candidates features analysis classifier tracking evaluation pipeline dataset labeling"
# Beside the flow: what they may include.
declare -A beside=([synth]="core frame")
programs="detector synth miner labeler trainer recorder bench ros adapt"

allowed_library() {  # area -> the library folders it may include
  local area="$1" before=""
  if [ -n "${beside[$area]+x}" ]; then echo "${beside[$area]} $area"; return; fi
  for f in $flow; do
    before="$before $f"
    if [ "$f" = "$area" ]; then echo "$before"; return; fi
  done
  echo "UNKNOWN"
}

bad=0
complain() { echo "$1: $2"; bad=1; }

# The library: src/AREA/*.cpp and include/rdsf/AREA/*.hpp.
for file in src/*/*.cpp include/rdsf/*/*.hpp; do
  area="$(basename "$(dirname "$file")")"
  allowed=" $(allowed_library "$area") "
  if [ "$allowed" = " UNKNOWN " ]; then complain "$file" "folder '$area' is not in scripts/include-check.sh"; continue; fi
  while IFS= read -r line; do  # bash's own matching: a process per line made this check take 47 s in CI
    [[ "$line" =~ ^#include\ [\<\"]([^\"\>]+)[\"\>] ]] || continue
    target="${BASH_REMATCH[1]}"
    case "$target" in
      rdsf/*/*)
        to="${target#rdsf/}"
        to="${to%%/*}"
        [[ "$allowed" == *" $to "* ]] || complain "$file" "includes $target: $area may include only: $(echo $allowed)"
        ;;
      boost/program_options*|opencv2/highgui*) complain "$file" "includes $target: the library has no command line and no window" ;;
      opencv2/imgcodecs*) [ "$file" = src/frame/image_codecs_module.cpp ] ||
        complain "$file" "includes $target: OpenCV's image codecs are called through rdsf/frame/image_codecs.hpp" ;;
      cli/*|gui/*) complain "$file" "includes $target: the library never includes cli/ or gui/" ;;
      */*.hpp) to="${target%%/*}"
        [[ " $programs " == *" $to "* ]] && complain "$file" "includes $target: the library never includes a program" ;;
    esac
  done < <(grep -E '^#include ' "$file" || true)
done

# cli/ and gui/: the library and themselves.
for file in cli/*.cpp cli/*.hpp gui/*.cpp gui/*.hpp; do
  own="$(dirname "$file")"
  while IFS= read -r target; do
    to="${target%%/*}"
    [ "$to" = rdsf ] || [ "$to" = "$own" ] || [[ " $programs " != *" $to "* ]] ||
      complain "$file" "includes $target: $own/ is shared by the programs and includes none of them"
  done < <(grep -hoE '^#include "[^"]+"' "$file" | sed -E 's/#include "([^"]+)"/\1/' || true)
done

# Program folders: the library, cli/, gui/ and their own folder.
for own in $programs; do
  for file in $(find "$own" -name '*.cpp' -o -name '*.hpp'); do
    while IFS= read -r target; do
      to="${target%%/*}"
      [ "$to" = "$target" ] && continue  # a file of the same folder
      [ "$to" = rdsf ] || [ "$to" = cli ] || [ "$to" = gui ] || [ "$to" = "$own" ] ||
        [[ " $programs " != *" $to "* ]] || complain "$file" "includes $target: a program includes no other program"
    done < <(grep -hoE '^#include "[^"]+"' "$file" | sed -E 's/#include "([^"]+)"/\1/' || true)
  done
done

if [ "$bad" = 1 ]; then
  echo "include-check.sh: includes point the wrong way (docs/architecture.md says which way they may)" >&2
  exit 1
fi
echo "every #include points the way docs/architecture.md says"
