#!/usr/bin/python3
"""Latency of rdsf_people seen from outside: subscribes to the depth image's camera_info topic and to
/people as raw messages (rospy.AnyMsg: nothing is deserialised but the header's first 12 bytes, seq and
stamp) and, for each People message, takes its arrival time minus the arrival time here of the
camera_info with the same stamp. A camera driver (and rosbag play) publishes the image and then its
camera_info, and the node starts on a frame when both are in; both messages reach this probe over TCP
like any other node, so this is the delay the node adds between a camera's frame and its people
(transport into the node, pairing, analysis, tracking, publishing, transport out). The probe subscribes to
camera_info rather than the image: a Python subscriber reading 600 KB images at 30 frames/s falls behind
on a loaded machine and would time its own lag. Prints one line on SIGINT: count, p50, p95, p99, max (ms,
nearest rank), camera_info messages without people, and People that came before their camera_info here.
The stamps repeat with every loop of a bag played with -l (1.53 s for 46 frames), so a camera_info older
than STALE_S is dropped unanswered rather than paired with the next loop's People of the same stamp.

    scripts/ros-latency-probe.py CAMERA_INFO_TOPIC PEOPLE_TOPIC      (run by scripts/ros-latency.sh)
"""
import math
import signal
import struct
import sys
import threading
import time

import rospy

STALE_S = 1.0


def percentile(values, p):
    if not values:
        return 0.0
    ordered = sorted(values)
    return ordered[max(0, math.ceil(p / 100.0 * len(ordered)) - 1)]


def main():
    depth_topic, people_topic = sys.argv[1], sys.argv[2]
    rospy.init_node("rdsf_latency_probe", anonymous=True, disable_signals=True)
    lock = threading.Lock()
    arrived = {}
    latency_ms = []
    counts = {"stale": 0, "early": 0}

    def stamp_of(message):
        _, secs, nsecs = struct.unpack_from("<III", message._buff, 0)
        return (secs, nsecs)

    def on_depth(message):
        now = time.monotonic()
        with lock:
            for stamp in [s for s, t in arrived.items() if now - t > STALE_S]:
                del arrived[stamp]
                counts["stale"] += 1
            arrived[stamp_of(message)] = now

    def on_people(message):
        now = time.monotonic()
        with lock:
            start = arrived.pop(stamp_of(message), None)
            if start is None:
                counts["early"] += 1
            elif now - start <= STALE_S:
                latency_ms.append((now - start) * 1000.0)
            else:
                counts["stale"] += 1

    rospy.Subscriber(depth_topic, rospy.AnyMsg, on_depth, queue_size=100, tcp_nodelay=True)
    rospy.Subscriber(people_topic, rospy.AnyMsg, on_people, queue_size=100, tcp_nodelay=True)
    stop = threading.Event()
    signal.signal(signal.SIGINT, lambda *_: stop.set())
    signal.signal(signal.SIGTERM, lambda *_: stop.set())
    while not stop.wait(0.2):
        pass
    with lock:
        values = list(latency_ms)
        unanswered = len(arrived) + counts["stale"]
        early = counts["early"]
    print("probe: %d frames, latency camera_info message to people p50 %.2f ms, p95 %.2f ms, p99 %.2f ms, max %.2f ms; "
          "%d camera_info messages without people; %d People before their camera_info reached the probe"
          % (len(values), percentile(values, 50), percentile(values, 95), percentile(values, 99),
             percentile(values, 100), unanswered, early),
          flush=True)
    rospy.signal_shutdown("done")


if __name__ == "__main__":
    main()
