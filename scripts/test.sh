#!/usr/bin/env bash
# Runs every test: installs what is missing, builds, then CTest (GoogleTest programs). Tests that read the
# real frames in ../shared/realdata skip with a message when that folder is absent.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
build_dir="${RDSF_BUILD_DIR:-build}"
# The shipped default model's recipe still trains, and two runs give the same bytes (a small model).
scripts/train-default-model.sh --quick
# ... and on the four-camera mix (docs/sensors.md): the four cameras' samples reach both sets.
scripts/train-default-model.sh --quick --cameras mix
# ... and people-near's (docs/quality.md, "people-near"): its near rooms' sets reach the training.
scripts/train-default-model.sh --quick --near-people
ctest --test-dir "$build_dir" --output-on-failure -j"$(nproc 2>/dev/null || echo 2)" --timeout 900
