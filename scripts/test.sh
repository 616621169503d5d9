#!/usr/bin/env bash
# Runs every test: installs what is missing, builds, then CTest (GoogleTest programs). Tests that read the
# real frames in ../shared/realdata skip with a message when that folder is absent.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
build_dir="${RDSF_BUILD_DIR:-build}"
export RDSF_SETUP_DONE="$build_dir"  # what follows needs no second look at the packages and the build
# The shipped default model's recipe still trains, and two runs give the same bytes (a small model);
# ... and on the four-camera mix (docs/sensors.md): the four cameras' samples reach both sets;
# ... and people-near's (docs/quality.md, "people-near"): its near rooms' sets reach the training.
# The three at once (each keeps about one core busy), each one's output shown in this order when it ends.
quick_checks=("" "--cameras mix" "--near-people")
logs=$(mktemp -d)
trap 'rm -rf "$logs"' EXIT
pids=()
for i in "${!quick_checks[@]}"; do
  read -r -a extra <<<"${quick_checks[$i]}"
  scripts/train-default-model.sh --quick "${extra[@]}" >"$logs/$i" 2>&1 &
  pids+=($!)
done
failed=0
for i in "${!pids[@]}"; do
  wait "${pids[$i]}" || failed=1
  cat "$logs/$i"
done
if ((failed)); then
  echo "test: a quick training of the default model's recipe failed (its lines above)" >&2
  exit 1
fi
ctest --test-dir "$build_dir" --output-on-failure -j"$(nproc 2>/dev/null || echo 2)" --timeout 900
