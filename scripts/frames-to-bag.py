#!/usr/bin/python3
"""Writes a ROS 1 bag from a folder of depth PNGs (NAME.depth.png, 16-bit millimetres, 0 = no reading) and
their colour frames (NAME.rgb.png, when present), as a depth camera driver would publish them.

    scripts/frames-to-bag.py FOLDER OUT.bag [--fps 30] [--depth-encoding 16UC1|32FC1] [--layout ros|registered|realsense]
                             [--compressed-depth png|rvl] [--compressed-colour png|jpeg]

Layout "ros" (the default; the topics of openni_launch / realsense2_camera):
  /camera/depth/image_raw    sensor_msgs/Image, 16UC1 millimetres (or 32FC1 metres, NaN = no reading)
  /camera/depth/camera_info  sensor_msgs/CameraInfo (K, P, size), one per depth frame, same stamp
  /camera/rgb/image_raw      sensor_msgs/Image rgb8 (or --colour-encoding bgr8), only for frames with colour
  /camera/rgb/camera_info    sensor_msgs/CameraInfo of the colour image (registered: the depth's model)
Layout "registered" (depth registered to the colour camera, as a robot's recorder may keep it: a Toyota
HSR's head camera in datasets/public/tue_hero):
  /camera/depth_registered/image_raw  sensor_msgs/Image, as above, in the colour camera's optical frame
  /camera/rgb/camera_info    sensor_msgs/CameraInfo, one per depth frame: the only one (none beside the depth)
  /camera/rgb/image_raw      sensor_msgs/Image rgb8, only for frames with colour
  (every header's frame_id is camera_rgb_optical_frame)
Layout "realsense" (RealSense Viewer's .bag recordings, the part of their layout rdsf reads):
  /file_version                              std_msgs/UInt32 3
  /device_0/sensor_0/Depth_0/image/data      sensor_msgs/Image mono16 (librealsense's name for Z16) in depth units
  /device_0/sensor_0/Depth_0/info/camera_info  sensor_msgs/CameraInfo (once)
  /device_0/sensor_0/option/Depth Units/value  std_msgs/Float32, metres per depth unit (--depth-unit-m)
  /device_0/sensor_1/Color_0/image/data      sensor_msgs/Image rgb8
  /device_0/sensor_1/Color_0/info/camera_info  sensor_msgs/CameraInfo (once)

Compressed (as `rosbag record` keeps a robot's image_transport topics; rdsf/frame/compressed_image.hpp):
--compressed-depth writes the depth as sensor_msgs/CompressedImage on DEPTH_TOPIC/compressedDepth, format
"ENC; compressedDepth png|rvl": a 12-byte header (int32 0, float32 A, float32 B), then the 16-bit samples as
a PNG or RVL; 16UC1 samples are the millimetres, 32FC1 ones the transport's inverse depth
q = trunc(A / d + B), A = 100 x 101, B = 1 - A / 10 m (its defaults; 0 beyond 10 m and where no reading).
--compressed-colour writes colour as CompressedImage on COLOUR_TOPIC/compressed, format
"rgb8; png compressed bgr8" (lossless) or "rgb8; jpeg compressed bgr8" (needs python3-opencv).

Frames are sorted by name (as rdsf reads the folder); frame i is stamped start + i / fps seconds, its
colour frame at the same instant plus --colour-offset-ms. The camera model is camera.yml beside the frames
when present (width, height, fx, fy, cx, cy, depth_unit_mm), else the Kinect v1 (fx = fy = 525, cx = 319.5,
cy = 239.5 at 640x480) scaled to the frame size; --fx/--fy/--cx/--cy override it.

The bag is written to OUT.bag.tmp and renamed when complete; an existing OUT.bag is kept unless --force.
Needs python3-rosbag, python3-sensor-msgs, python3-numpy and python3-png (Debian 12; scripts/setup.sh).
"""
import argparse
import io
import os
import re
import struct
import sys

try:
    import numpy as np
    import png
    import rosbag
    import rospy
    from sensor_msgs.msg import CameraInfo, CompressedImage, Image
    from std_msgs.msg import Float32, UInt32
except ImportError as error:
    sys.exit("frames-to-bag: %s (install python3-rosbag python3-sensor-msgs python3-numpy python3-png)" % error)

DEPTH_SUFFIX = ".depth.png"
COLOUR_SUFFIX = ".rgb.png"

LAYOUTS = {
    "ros": {
        "depth": "/camera/depth/image_raw",
        "depth_info": "/camera/depth/camera_info",
        "colour": "/camera/rgb/image_raw",
        "colour_info": "/camera/rgb/camera_info",
        "frame_id": "camera_depth_optical_frame",
    },
    "registered": {
        "depth": "/camera/depth_registered/image_raw",
        "depth_info": "/camera/rgb/camera_info",
        "colour": "/camera/rgb/image_raw",
        "colour_info": None,
        "frame_id": "camera_rgb_optical_frame",
    },
    "realsense": {
        "depth": "/device_0/sensor_0/Depth_0/image/data",
        "depth_info": "/device_0/sensor_0/Depth_0/info/camera_info",
        "depth_units": "/device_0/sensor_0/option/Depth Units/value",
        "colour": "/device_0/sensor_1/Color_0/image/data",
        "colour_info": "/device_0/sensor_1/Color_0/info/camera_info",
        "frame_id": "0",
    },
}


def fail(message):
    sys.exit("frames-to-bag: " + message)


def read_png(path):
    """The PNG as a numpy array: (h, w) uint16 for 16-bit grey, (h, w, 3) uint8 for colour."""
    try:
        width, height, rows, info = png.Reader(filename=path).asDirect()
        planes = info["planes"]
        dtype = np.uint16 if info["bitdepth"] > 8 else np.uint8
        image = np.vstack([np.asarray(row, dtype=dtype) for row in rows])
    except (png.Error, OSError, ValueError) as error:
        fail("%s: cannot be read as PNG (%s)" % (path, error))
    return image.reshape(height, width, planes) if planes > 1 else image.reshape(height, width)


def read_camera_yml(path):
    """The scalar keys of camera.yml ("key: value" lines; rdsf/frame/camera_file.hpp, format rdsf-camera 1)."""
    model = {}
    with open(path, encoding="utf-8") as stream:
        for line in stream:
            match = re.match(r"^\s*([A-Za-z_]+)\s*:\s*([-+0-9.eE]+)\s*$", line)
            if match:
                model[match.group(1)] = float(match.group(2))
    for key in ("width_px", "height_px", "fx_px", "fy_px", "cx_px", "cy_px"):
        if key not in model:
            fail("%s: has no %s" % (path, key))
    if model.get("depth_unit_mm", 1.0) != 1.0:
        fail("%s: depth_unit_mm %g: only millimetre frames are written" % (path, model["depth_unit_mm"]))
    return {key[:-3]: value for key, value in model.items() if key.endswith("_px")}


def camera_model(folder, width, height, args):
    yml = os.path.join(folder, "camera.yml")
    if os.path.exists(yml):
        model = read_camera_yml(yml)
        if int(model["width"]) != width or int(model["height"]) != height:
            fail("%s: says %dx%d, the frames are %dx%d" % (yml, model["width"], model["height"], width, height))
    else:  # the Kinect v1 default scaled to the frame size, as rdsf does
        sx, sy = width / 640.0, height / 480.0
        model = {"fx": 525.0 * sx, "fy": 525.0 * sy, "cx": 320.0 * sx - 0.5, "cy": 240.0 * sy - 0.5}
    for key in ("fx", "fy", "cx", "cy"):
        if getattr(args, key) is not None:
            model[key] = getattr(args, key)
    return model


def camera_info(header, width, height, model):
    info = CameraInfo()
    info.header = header
    info.width, info.height = width, height
    info.distortion_model = "plumb_bob"
    info.D = [0.0] * 5
    info.K = [model["fx"], 0.0, model["cx"], 0.0, model["fy"], model["cy"], 0.0, 0.0, 1.0]
    info.R = [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0]
    info.P = [model["fx"], 0.0, model["cx"], 0.0, 0.0, model["fy"], model["cy"], 0.0, 0.0, 0.0, 1.0, 0.0]
    return info


def image_message(header, array, encoding):
    message = Image()
    message.header = header
    message.height, message.width = array.shape[0], array.shape[1]
    message.encoding = encoding
    message.is_bigendian = 0
    contiguous = np.ascontiguousarray(array)
    message.step = contiguous.strides[0]
    message.data = contiguous.tobytes()
    return message


def depth_array(depth_mm, encoding, depth_unit_mm):
    if encoding == "32FC1":  # metres, NaN where there is no reading (REP 118)
        metres = depth_mm.astype(np.float32) / np.float32(1000.0)
        metres[depth_mm == 0] = np.nan
        return metres.astype("<f4")
    units = np.rint(depth_mm.astype(np.float64) / depth_unit_mm)
    if units.max(initial=0) > 65535:
        fail("depth exceeds 65535 units of %g mm" % depth_unit_mm)
    return units.astype("<u2")


QUANTISATION_Z0 = 100.0   # compressed_depth_image_transport's depth_quantization default
QUANTISATION_MAX_M = 10.0  # its depth_max default (m)


def png_bytes(array):
    """A PNG of a (h, w) uint16 grey or (h, w, 3) uint8 RGB array."""
    height, width = array.shape[:2]
    colour = array.ndim == 3
    writer = png.Writer(width, height, greyscale=not colour, bitdepth=8 if colour else 16)
    stream = io.BytesIO()
    writer.write(stream, array.reshape(height, -1).tolist())
    return stream.getvalue()


def rvl_bytes(samples):
    """RVL (Wilson 2017) of 16-bit samples in row order: uint32 columns, uint32 rows, then the stream of
    32-bit little-endian words, each eight 4-bit groups from its most significant end (3 value bits, least
    significant first, and a high bit saying another group follows); the values: a count of zeros, a count
    of non-zeros, each non-zero's zigzag-coded difference from the previous non-zero (0 before the first)."""
    words, state = [], [0, 0]  # the word being filled, its groups

    def put(value):
        while True:
            group, value = value & 7, value >> 3
            state[0] = ((state[0] << 4) | group | (8 if value else 0)) & 0xFFFFFFFF
            state[1] += 1
            if state[1] == 8:
                words.append(state[0])
                state[0], state[1] = 0, 0
            if not value:
                return

    flat = samples.ravel().astype(np.int64)
    nonzero = flat != 0
    # Where runs of zeros and non-zeros start and end.
    edges = np.flatnonzero(np.diff(nonzero.astype(np.int8))) + 1
    bounds = np.concatenate(([0], edges, [flat.size]))
    differences = np.diff(np.concatenate(([0], flat[nonzero])))
    zigzag = np.where(differences >= 0, 2 * differences, -2 * differences - 1).tolist()
    taken = 0
    run = 0
    while run + 1 < len(bounds):
        start, end = bounds[run], bounds[run + 1]
        if nonzero[start]:  # a run of non-zeros with no zeros before it
            put(0)
        else:
            put(int(end - start))
            run += 1
            if run + 1 >= len(bounds):
                put(0)
                break
            start, end = bounds[run], bounds[run + 1]
        put(int(end - start))
        for value in zigzag[taken:taken + (end - start)]:
            put(value)
        taken += end - start
        run += 1
    if state[1]:
        words.append((state[0] << (4 * (8 - state[1]))) & 0xFFFFFFFF)
    height, width = samples.shape
    return struct.pack("<II", width, height) + struct.pack("<%dI" % len(words), *words)


def compressed_depth_message(header, depth_mm, encoding, compression):
    message = CompressedImage()
    message.header = header
    message.format = encoding + "; compressedDepth " + compression
    a = b = np.float32(0.0)
    if encoding == "32FC1":
        a = np.float32(QUANTISATION_Z0 * (QUANTISATION_Z0 + 1.0))
        b = np.float32(1.0 - a / np.float32(QUANTISATION_MAX_M))
        metres = depth_mm.astype(np.float32) / np.float32(1000.0)
        keep = (depth_mm > 0) & (metres < QUANTISATION_MAX_M)
        inverse = np.zeros(depth_mm.shape, np.float32)
        inverse[keep] = a / metres[keep] + b
        samples = np.minimum(inverse, 65535).astype(np.uint16)
    else:
        samples = depth_mm.astype(np.uint16)
    body = rvl_bytes(samples) if compression == "rvl" else png_bytes(samples)
    message.data = struct.pack("<iff", 0, float(a), float(b)) + body
    return message


def compressed_colour_message(header, rgb, compression):
    message = CompressedImage()
    message.header = header
    message.format = "rgb8; %s compressed bgr8" % compression
    if compression == "png":
        message.data = png_bytes(np.ascontiguousarray(rgb))
    else:
        try:
            import cv2
        except ImportError:
            fail("--compressed-colour jpeg needs python3-opencv")
        ok, encoded = cv2.imencode(".jpg", np.ascontiguousarray(rgb[:, :, ::-1]))
        if not ok:
            fail("cannot encode a JPEG")
        message.data = encoded.tobytes()
    return message


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("folder", help="folder of NAME.depth.png (and NAME.rgb.png) frames")
    parser.add_argument("bag", help="the bag to write")
    parser.add_argument("--fps", type=float, default=30.0, help="frames per second of the stamps (default 30)")
    parser.add_argument("--start", type=float, default=1.0, help="stamp of the first frame, in seconds (default 1)")
    parser.add_argument("--depth-encoding", choices=["16UC1", "32FC1"], default="16UC1",
                        help="16UC1 millimetres (default) or 32FC1 metres (layout ros only)")
    parser.add_argument("--colour-encoding", choices=["rgb8", "bgr8"], default="rgb8", help="default rgb8")
    parser.add_argument("--no-colour", action="store_true", help="write no colour frames")
    parser.add_argument("--no-camera-info", action="store_true", help="write no CameraInfo (to test fall-backs)")
    parser.add_argument("--colour-offset-ms", type=float, default=0.0,
                        help="colour stamps this much after their depth frame (default 0)")
    parser.add_argument("--layout", choices=sorted(LAYOUTS), default="ros", help="topic layout (default ros)")
    parser.add_argument("--depth-unit-m", type=float, default=0.001,
                        help="realsense layout: metres per depth unit written (default 0.001)")
    parser.add_argument("--depth-topic", help="override the layout's depth topic")
    parser.add_argument("--colour-topic", help="override the layout's colour topic")
    parser.add_argument("--first", type=int, default=0, help="skip the frames before this index")
    parser.add_argument("--count", type=int, default=0, help="write at most this many frames (0: all)")
    for key in ("fx", "fy", "cx", "cy"):
        parser.add_argument("--" + key, type=float, help="override the camera model's " + key + " (px)")
    parser.add_argument("--compressed-depth", choices=["png", "rvl"],
                        help="depth as compressedDepth on DEPTH_TOPIC/compressedDepth (layouts ros, registered)")
    parser.add_argument("--compressed-colour", choices=["png", "jpeg"],
                        help="colour as CompressedImage on COLOUR_TOPIC/compressed")
    parser.add_argument("--force", action="store_true", help="replace an existing bag")
    args = parser.parse_args()

    if args.fps <= 0:
        fail("--fps must be positive")
    if args.layout == "realsense" and args.depth_encoding != "16UC1":
        fail("the realsense layout stores 16UC1 depth units only")
    if args.layout == "realsense" and (args.compressed_depth or args.compressed_colour):
        fail("the realsense layout stores raw images only")
    names = sorted(n[: -len(DEPTH_SUFFIX)] for n in os.listdir(args.folder) if n.endswith(DEPTH_SUFFIX))
    names = names[args.first:]
    if args.count > 0:
        names = names[: args.count]
    if not names:
        fail("%s: holds no *%s frames" % (args.folder, DEPTH_SUFFIX))
    if os.path.exists(args.bag) and not args.force:
        fail("%s: exists (--force replaces it)" % args.bag)

    layout = dict(LAYOUTS[args.layout])
    layout["depth"] = args.depth_topic or layout["depth"]
    layout["colour"] = args.colour_topic or layout["colour"]
    if args.compressed_depth:
        layout["depth"] += "/compressedDepth"  # its camera_info stays beside the image topic
    if args.compressed_colour:
        layout["colour"] += "/compressed"
    temporary = args.bag + ".tmp"
    model = None
    colour_frames = 0
    bag = rosbag.Bag(temporary, "w")
    try:
        for index, name in enumerate(names):
            depth_mm = read_png(os.path.join(args.folder, name + DEPTH_SUFFIX))
            if depth_mm.ndim != 2 or depth_mm.dtype != np.uint16:
                fail("%s%s: not a 16-bit single-channel depth PNG" % (name, DEPTH_SUFFIX))
            height, width = depth_mm.shape
            if model is None:
                model = camera_model(args.folder, width, height, args)
            stamp = rospy.Time.from_sec(args.start + index / args.fps)
            header = rospy.Header(seq=index, stamp=stamp, frame_id=layout["frame_id"])
            if args.layout == "realsense" and index == 0:
                bag.write("/file_version", UInt32(data=3), stamp)
                bag.write(layout["depth_units"], Float32(data=args.depth_unit_m), stamp)
            unit_mm = args.depth_unit_m * 1000.0 if args.layout == "realsense" else 1.0
            encoding = "mono16" if args.layout == "realsense" else args.depth_encoding
            if args.compressed_depth:
                depth_message = compressed_depth_message(header, depth_mm, args.depth_encoding, args.compressed_depth)
            else:
                depth_message = image_message(header, depth_array(depth_mm, args.depth_encoding, unit_mm), encoding)
            bag.write(layout["depth"], depth_message, stamp)
            if not args.no_camera_info and (args.layout != "realsense" or index == 0):
                bag.write(layout["depth_info"], camera_info(header, width, height, model), stamp)
            colour_path = os.path.join(args.folder, name + COLOUR_SUFFIX)
            if args.no_colour or not os.path.exists(colour_path):
                continue
            rgb = read_png(colour_path)
            if rgb.ndim != 3 or rgb.shape[2] < 3 or rgb.dtype != np.uint8:
                fail("%s: not an 8-bit colour PNG" % colour_path)
            if rgb.shape[:2] != depth_mm.shape:
                fail("%s: is %dx%d, its depth frame %dx%d" % (colour_path, rgb.shape[1], rgb.shape[0], width, height))
            rgb = rgb[:, :, :3]
            colour_stamp = rospy.Time.from_sec(args.start + index / args.fps + args.colour_offset_ms / 1000.0)
            colour_header = rospy.Header(seq=index, stamp=colour_stamp, frame_id=layout["frame_id"])
            if args.compressed_colour:
                colour_message = compressed_colour_message(colour_header, rgb, args.compressed_colour)
            else:
                colour = rgb if args.colour_encoding == "rgb8" else rgb[:, :, ::-1]
                colour_message = image_message(colour_header, colour, args.colour_encoding)
            bag.write(layout["colour"], colour_message, colour_stamp)
            if layout["colour_info"] and not args.no_camera_info and (args.layout == "ros" or colour_frames == 0):
                bag.write(layout["colour_info"], camera_info(colour_header, width, height, model), colour_stamp)
            colour_frames += 1
    except BaseException:
        bag.close()
        os.remove(temporary)
        raise
    bag.close()
    with open(temporary, "rb") as stream:
        os.fsync(stream.fileno())
    os.replace(temporary, args.bag)
    print("frames-to-bag: wrote %s (%d depth frames, %d colour frames, %s, %g fps, layout %s)"
          % (args.bag, len(names), colour_frames, args.depth_encoding, args.fps, args.layout))


if __name__ == "__main__":
    main()
