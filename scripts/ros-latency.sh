#!/usr/bin/env bash
# Latency of the ROS node rdsf_people at a camera's rate (docs/ros.md, "Latency"): a roscore of its own on a
# free port, the node, a bag written from real frames (scripts/frames-to-bag.py) played in a loop at its
# 30 frames/s by `rosbag play -l`, and scripts/ros-latency-probe.py subscribed to the depth camera_info
# topic and to /people. Three runs: depth only (the 46 frames of ../shared/realdata/people), depth with colour
# (the frames of that folder that have a colour image, --colour on: a frame takes the colour image already
# there, the default), the same with --colour-wait true (a frame waits for its own colour image), and depth only
# as a robot streams it compressed (compressedDepth png, --depth-transport compressedDepth: the node decodes each
# message). Prints per run the node's own line (depth
# message in the node to people published: p50/p95/p99/max, frames dropped) and the probe's (camera_info
# message to people, both seen from another node). A measurement, not a test: no figure is asserted.
#   scripts/ros-latency.sh [--seconds 60] [--threads 2] [--frames DIR] [--build-dir DIR]
# Defaults: as shown; --frames ../shared/realdata/people, --build-dir $RDSF_BUILD_DIR, else build.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/lib/options.sh
seconds=60
threads=2
frames=../shared/realdata/people
build_dir="${RDSF_BUILD_DIR:-build}"
script_options ros-latency.sh --seconds=seconds --threads=threads --frames=frames --build-dir=build_dir -- "$@"
node_program="$build_dir/ros/rdsf_people"
[ -x "$node_program" ] || { echo "ros-latency.sh: error: $node_program is missing (build with ROS 1: scripts/setup.sh)" >&2; exit 1; }
[ -d "$frames" ] || { echo "ros-latency.sh: error: $frames: no such folder of frames" >&2; exit 1; }
command -v roscore >/dev/null || { echo "ros-latency.sh: error: roscore not found (apt-get install ros-core)" >&2; exit 1; }

work="$(mktemp -d)"
pids=()
cleanup() {
  for pid in "${pids[@]}"; do kill -INT -- "-$pid" 2>/dev/null || true; done
  sleep 1
  for pid in "${pids[@]}"; do kill -KILL -- "-$pid" 2>/dev/null || true; done
  rm -rf "$work"
}
trap cleanup EXIT

# The bags: every frame, and the frames with colour.
/usr/bin/python3 scripts/frames-to-bag.py "$frames" "$work/depth.bag" --no-colour >&2
/usr/bin/python3 scripts/frames-to-bag.py "$frames" "$work/compressed.bag" --no-colour --compressed-depth png >&2
mkdir "$work/colour"
for rgb in "$frames"/*.rgb.png; do
  [ -e "$rgb" ] || continue
  name="$(basename "$rgb" .rgb.png)"
  ln -s "$(realpath "$frames/$name.depth.png")" "$work/colour/$name.depth.png"
  ln -s "$(realpath "$rgb")" "$work/colour/$name.rgb.png"
done
have_colour=0
if ls "$work/colour"/*.depth.png >/dev/null 2>&1; then
  /usr/bin/python3 scripts/frames-to-bag.py "$work/colour" "$work/colour.bag" >&2
  have_colour=1
fi

port="$(/usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')"
export ROS_MASTER_URI="http://127.0.0.1:$port" ROS_HOSTNAME=127.0.0.1 ROS_HOME="$work/ros_home" ROS_LOG_DIR="$work/ros_log"
setsid roscore -p "$port" >"$work/roscore.log" 2>&1 &
pids+=($!)
disown
for _ in $(seq 100); do rostopic list >/dev/null 2>&1 && break; sleep 0.2; done
rostopic list >/dev/null 2>&1 || { echo "ros-latency.sh: error: roscore did not start: $(tail -3 "$work/roscore.log")" >&2; exit 1; }

echo "ros-latency.sh: $(date -u +'%Y-%m-%d %H:%M UTC'), $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg); $seconds s per run at 30 frames/s, $threads live workers"
run_case() {  # NAME BAG COLOUR [NODE OPTION ...]
  local name="$1" bag="$2" colour="$3" node probe
  shift 3
  setsid "$node_program" depth/image:=/camera/depth/image_raw rgb/image:=/camera/rgb/image_raw \
    --models-dir models --threads "$threads" --colour "$colour" "$@" >"$work/node-$name.log" 2>&1 &
  node=$!
  pids+=("$node")
  disown
  for _ in $(seq 100); do grep -q "rdsf_people: model" "$work/node-$name.log" && break; sleep 0.2; done
  setsid /usr/bin/python3 scripts/ros-latency-probe.py /camera/depth/camera_info /people >"$work/probe-$name.log" 2>&1 &
  probe=$!
  pids+=("$probe")
  disown
  sleep 2
  timeout --signal=INT "$seconds" rosbag play -q -l "$bag" >"$work/play-$name.log" 2>&1 || true
  sleep 1
  kill -INT -- "-$probe" "-$node" 2>/dev/null || true
  for _ in $(seq 50); do kill -0 "$probe" 2>/dev/null || kill -0 "$node" 2>/dev/null || break; sleep 0.2; done
  echo "$name: $(grep -h "rdsf_people: [0-9]" "$work/node-$name.log" || tail -2 "$work/node-$name.log")"
  echo "$name: $(grep -h "^probe:" "$work/probe-$name.log" || tail -2 "$work/probe-$name.log")"
}
run_case depth "$work/depth.bag" false
if [ "$have_colour" = 1 ]; then
  run_case colour "$work/colour.bag" true
  run_case colour-wait "$work/colour.bag" true --colour-wait true
fi
run_case compressed "$work/compressed.bag" false --depth-transport compressedDepth
echo "ros-latency.sh: load average at the end $(cut -d' ' -f1-3 /proc/loadavg)"
