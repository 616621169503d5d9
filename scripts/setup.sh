#!/usr/bin/env bash
# Installs the Debian 12 packages the workbench needs (only those missing; uses sudo when not root), then
# configures and builds everything into build/ (or $RDSF_BUILD_DIR). Safe to run again: it only does
# what is left to do.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir="${RDSF_BUILD_DIR:-build}"
# scripts/test.sh runs this once and sets RDSF_SETUP_DONE to the build folder: the scripts it runs after
# (train-default-model.sh) need not look at the packages and the build again.
if [ "${RDSF_SETUP_DONE:-}" = "$build_dir" ]; then exit 0; fi

packages=(
  g++ cmake make pkg-config
  libopencv-dev libeigen3-dev libopenni2-dev libboost-program-options-dev
  libgtest-dev libbenchmark-dev libdeflate-dev
  xvfb xauth xdotool x11-apps
  # ROS 1 bags: the bag frame source (librosbag-dev, libsensor-msgs-dev) and scripts/frames-to-bag.py
  librosbag-dev libsensor-msgs-dev python3-rosbag python3-sensor-msgs python3-numpy python3-png
  # ... JPEG colour topics of the test bags (scripts/frames-to-bag.py --compressed-colour jpeg): the path on
  # which the library opens OpenCV's image codecs (frame/image_codecs.hpp)
  python3-opencv
)
# The ROS 1 node rdsf_people (ros/, docs/ros.md) and its test: libraries, the message generator and the
# definitions it reads, roscore, rosbag play, and what scripts/frames-to-bag.py needs to write the test's bag.
packages+=(
  libroscpp-dev libmessage-filters-dev libsensor-msgs-dev libcv-bridge-dev libimage-transport-dev libvisualization-msgs-dev
  libdiagnostic-msgs-dev python3-genmsg python3-gencpp ros-std-msgs ros-geometry-msgs ros-sensor-msgs
  ros-core python3-rosbag python3-sensor-msgs python3-numpy python3-png
  libopenmpi-dev openmpi-bin parallel slurm-wlm  # issue 37: mpirun rdsf-train, shard-mine.sh, the Slurm array test
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

jobs="$(nproc 2>/dev/null || echo 2)"
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release >/dev/null
log="$build_dir/build.log"
echo "setup: building with $jobs jobs (log: $log)"
if ! cmake --build "$build_dir" -j"$jobs" >"$log" 2>&1; then
  grep -E -A5 "error" "$log" | head -60
  echo "setup: build failed (full log: $log)" >&2
  exit 1
fi
grep -E "warning:" "$log" | head -20 || true
echo "setup: built into $build_dir"
