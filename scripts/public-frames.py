#!/usr/bin/env python3
"""public-frames.py OUT --pcl GITDIR --pcl-data GITDIR --open3d GITDIR --tue GITDIR

Converts the public real depth frames of datasets/public/ (datasets/public/README.md) from the git
repositories they were found in (as the search tool's fetch brings them: bare git folders), at the commits
recorded there, into OUT/<SOURCE>/: NAME.depth.png (16-bit, millimetres, 0 = no reading), NAME.rgb.png when
the source has colour, boxes.csv where people are labelled, README.md (source, commit, path, licence, people) and the licence text. Nothing is
downloaded; the same repositories give the same bytes.

Conversions:
  organised PCD clouds (640x480, Kinect-class): depth_mm = round(z * 1000), 0 where z is NaN; colour from
    the packed rgb / rgba field. binary_compressed data is LZF (decompressed here) stored field by field.
  TUM RGB-D depth PNGs: 5000 units a metre, depth_mm = round(value / 5).
  ROS 1 bags (a robot's head camera, 32FC1 metres registered to its colour camera): depth_mm = round(1000 * m)
    to the nearest even millimetre on ties, 0 where m is NaN, inf, <= 0 or beyond 65.535 m (as rdsf's bag
    source reads it); colour the bag's rgb8 image; camera.yml from the colour camera's CameraInfo K. The
    first bag is kept beside the frames, so that a test reads a bag nobody here wrote.

Exit codes: 0 done, 1 a repository or file that cannot be read (one line naming it), 2 usage.
"""
import argparse
import io
import os
import struct
import subprocess
import sys

import numpy
import png

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
import depth_frames  # noqa: E402

PCL_COMMIT = "1fdb03883eab28f642e938d9bf4d317903212cb4"
PCL_DATA_COMMIT = "5c26bdd0591ba150b91858b5c9fe5e91cb39ae86"
OPEN3D_COMMIT = "e4315a8033dc9e28386fc34d4896d9bb0a3bf91b"
TUE_COMMIT = "9b5f0f8d96809f6241f2fab16471bb4798f1063b"

# The people of pcl_people's frame, drawn by hand (x, y, w, h in pixels), left to right.
BOXES = {"five_people": [(20, 68, 138, 408), (143, 98, 103, 378), (279, 103, 94, 337), (362, 103, 108, 347),
                         (470, 50, 136, 426)]}
# tue_hero's people (x, y, w, h, visible fraction): person 1 stands 1.7-2.0 m away, the tight box of his depth
# pixels (the region of readings that differ from a neighbour by less than 60 mm, grown from his torso); 2-4 sit
# in a row at a table by the left border (2 at 1.9-2.4 m cut by the border, 3 at 3.3 m behind 2, 4 at 4.9 m
# behind a chair with a jacket on it), each mostly hidden: "don't care" (visible < 0.5), the boxes of their
# readings. People beyond the sensor's range (a walker at about 10 m in hall_2 to hall_4) have no readings and
# no box. Checked by eye on the depth and colour frames.
BOXES.update({
    "hall_1": [(238, 61, 142, 400, 1.0), (5, 200, 106, 260, 0.4), (56, 217, 93, 243, 0.3), (132, 243, 66, 128, 0.2)],
    "hall_2": [(272, 30, 205, 432, 1.0), (5, 201, 108, 259, 0.4), (53, 216, 80, 198, 0.3), (136, 245, 62, 117, 0.2)],
    "hall_3": [(272, 28, 205, 434, 1.0), (5, 196, 106, 264, 0.4), (44, 217, 89, 195, 0.3), (129, 243, 69, 128, 0.2)],
    "hall_4": [(227, 30, 215, 432, 1.0), (5, 198, 108, 262, 0.4), (44, 216, 89, 199, 0.3), (129, 245, 70, 117, 0.2)],
    "hall_5": [(233, 30, 209, 432, 1.0), (5, 199, 106, 261, 0.4), (44, 216, 88, 202, 0.3), (127, 246, 71, 116, 0.2)],
})
TUE_BAGS = "people_recognition_3d/test/assets/"
# The licence: the repository has no licence file; its packages' package.xml files declare MIT.
MIT_TEXT = """MIT License

The frames, boxes aside, and the bag of this folder come from https://github.com/tue-robotics/people_recognition
(people_recognition_3d/test/assets/*.bag), whose package.xml files (people_recognition_3d/package.xml,
people_detection_3d/package.xml) declare the MIT licence; the repository holds no licence text of its own, so
the MIT licence's text is given here with the holder the repository names.

Copyright (c) 2019 the authors of tue-robotics/people_recognition (TU/e Robotics, Eindhoven University of Technology)

Permission is hereby granted, free of charge, to any person obtaining a copy of this software and associated
documentation files (the "Software"), to deal in the Software without restriction, including without limitation
the rights to use, copy, modify, merge, publish, distribute, sublicense, and/or sell copies of the Software, and
to permit persons to whom the Software is furnished to do so, subject to the following conditions:

The above copyright notice and this permission notice shall be included in all copies or substantial portions
of the Software.

THE SOFTWARE IS PROVIDED "AS IS", WITHOUT WARRANTY OF ANY KIND, EXPRESS OR IMPLIED, INCLUDING BUT NOT LIMITED TO
THE WARRANTIES OF MERCHANTABILITY, FITNESS FOR A PARTICULAR PURPOSE AND NONINFRINGEMENT. IN NO EVENT SHALL THE
AUTHORS OR COPYRIGHT HOLDERS BE LIABLE FOR ANY CLAIM, DAMAGES OR OTHER LIABILITY, WHETHER IN AN ACTION OF
CONTRACT, TORT OR OTHERWISE, ARISING FROM, OUT OF OR IN CONNECTION WITH THE SOFTWARE OR THE USE OR OTHER
DEALINGS IN THE SOFTWARE.
"""

# SOURCE -> (repository option, repository name, commit, licence, licence file, people, description,
#            [(frame NAME, path in the repository, what it shows)])
SOURCES = {
    "pcl_rooms": ("pcl_data", "PointCloudLibrary/data", PCL_DATA_COMMIT, "BSD-3-Clause", "LICENSE", "none",
                  "Kinect-class organised clouds of PCL's tutorials: an office corner from a moving camera and an "
                  "office chair, drawers and a door seen from above",
                  [("pairwise_1", "tutorials/pairwise/capture0001.pcd", "office corner, blinds, radiator, plant, desk"),
                   ("pairwise_2", "tutorials/pairwise/capture0002.pcd", "the same corner, camera moved"),
                   ("pairwise_3", "tutorials/pairwise/capture0003.pcd", "the same corner, camera moved"),
                   ("pairwise_4", "tutorials/pairwise/capture0004.pcd", "the same corner, camera moved"),
                   ("pairwise_5", "tutorials/pairwise/capture0005.pcd", "the same corner, camera moved"),
                   ("chair_bottles", "tutorials/region_growing_rgb_tutorial.pcd",
                    "an office chair, drawers and a door seen from above")]),
    "pcl_people": ("pcl", "PointCloudLibrary/pcl", PCL_COMMIT, "BSD-3-Clause", "LICENSE.txt",
                   "5, in boxes.csv (frame,person,x,y,w,h: the tight box of each person's visible pixels, drawn by "
                   "hand on the colour frame, which the organised cloud registers to the depth; feet and legs cut by "
                   "the image's bottom edge end there)",
                   "Kinect-class organised clouds with people (the cloud PCL's people-detector test runs on)",
                   [("five_people", "test/five_people.pcd", "five people walking away down a corridor, 1.8-3.5 m")]),
    "tum_open3d": ("open3d", "Acidburn0zzz/Open3D", OPEN3D_COMMIT, "CC BY 4.0", "LICENSE", "none",
                   "one TUM RGB-D benchmark frame (Kinect v1) kept as Open3D's test data; its sequence is not named "
                   "there. TUM RGB-D data: CC BY 4.0 (Sturm et al., IROS 2012); Open3D's code and the copy: MIT",
                   [("desk_chairs", "examples/TestData/RGBD/other_formats/TUM_depth.png",
                     "a desk, two office chairs, a partition wall")]),
    "tue_hero": ("tue", "tue-robotics/people_recognition", TUE_COMMIT, "MIT", "LICENSE",
                 "5 counted (one man standing 1.7-2.0 m away, in every frame) and 15 don't-care (three people seated "
                 "in a row by the left border, mostly hidden), in boxes.csv (frame,person,x,y,w,h,visible_fraction: "
                 "the tight boxes of their depth readings, drawn by rule and checked by eye; visible < 0.5 is don't "
                 "care)",
                 "A Toyota HSR robot's head camera (an Xtion-class RGB-D sensor, depth registered to colour, 32FC1 "
                 "metres) in a RoboCup venue hall: a high hall whose far end and shiny floor give no readings (a "
                 "third of the pixels have one), shelves, a table, people seated in a row; five single-frame ROS 1 "
                 "bags kept as the test data of a people detector. The colour image's stamp is 110-340 ms after the "
                 "depth's (the table); the man stands still or gestures",
                 [("hall_1", TUE_BAGS + "2019-05-03-12-41-38.bag", "standing, turned to his right, phone in hand"),
                  ("hall_2", TUE_BAGS + "2019-05-03-12-42-18.bag", "standing, facing the robot, hand on hip"),
                  ("hall_3", TUE_BAGS + "2019-05-03-12-42-25.bag", "the same pose, 7 s later"),
                  ("hall_4", TUE_BAGS + "2019-05-03-12-42-30.bag", "gesturing, both hands out"),
                  ("hall_5", TUE_BAGS + "2019-05-03-12-42-34.bag", "gesturing, both hands out")]),
}


class SourceError(Exception):
    pass


def git_blob(gitdir, commit, path):
    r = subprocess.run(["git", "--git-dir", gitdir, "show", f"{commit}:{path}"], capture_output=True)
    if r.returncode != 0:
        raise SourceError(f"{gitdir}: cannot read {path} at {commit[:8]}: "
                          f"{r.stderr.decode(errors='replace').strip().splitlines()[-1:]}")
    return r.stdout


def lzf_decompress(data, size):
    """LZF (liblzf's format, as PCL's binary_compressed uses): literal runs and back references."""
    out = bytearray(size)
    i = o = 0
    n = len(data)
    while i < n:
        ctrl = data[i]
        i += 1
        if ctrl < 32:  # a literal run of ctrl + 1 bytes
            length = ctrl + 1
            out[o:o + length] = data[i:i + length]
            i += length
            o += length
        else:  # a back reference
            length = ctrl >> 5
            if length == 7:
                length += data[i]
                i += 1
            ref = o - ((ctrl & 0x1f) << 8) - data[i] - 1
            i += 1
            length += 2
            if ref < 0 or o + length > size:
                raise ValueError("corrupt LZF data")
            for k in range(length):  # may overlap itself
                out[o + k] = out[ref + k]
            o += length
    if o != size:
        raise ValueError(f"LZF data gives {o} bytes, the header says {size}")
    return bytes(out)


def read_pcd(blob, name):
    """An organised PCD cloud as (depth_mm uint16 HxW, rgb uint8 HxWx3 or None)."""
    header = {}
    pos = 0
    while True:
        end = blob.index(b"\n", pos)
        line = blob[pos:end].decode("ascii").strip()
        pos = end + 1
        if not line or line.startswith("#"):
            continue
        key, _, value = line.partition(" ")
        header[key] = value.split()
        if key == "DATA":
            break
    fields, sizes = header["FIELDS"], [int(s) for s in header["SIZE"]]
    width, height = int(header["WIDTH"][0]), int(header["HEIGHT"][0])
    if height <= 1 or any(int(c) != 1 for c in header["COUNT"]) or any(s != 4 for s in sizes):
        raise SourceError(f"{name}: not an organised cloud of 4-byte fields")
    count = width * height
    kind = header["DATA"][0]
    if kind == "binary_compressed":
        compressed, raw_size = struct.unpack_from("<II", blob, pos)
        raw = lzf_decompress(blob[pos + 8:pos + 8 + compressed], raw_size)
        columns = {f: raw[k * 4 * count:(k + 1) * 4 * count] for k, f in enumerate(fields)}  # field by field
    elif kind == "binary":
        rows = numpy.frombuffer(blob[pos:pos + 4 * len(fields) * count], dtype=numpy.uint32).reshape(count, -1)
        columns = {f: rows[:, k].tobytes() for k, f in enumerate(fields)}
    else:
        raise SourceError(f"{name}: PCD data '{kind}' is not converted here")
    z = numpy.frombuffer(columns["z"], dtype="<f4").reshape(height, width)
    depth = numpy.where(numpy.isfinite(z), numpy.round(numpy.nan_to_num(z) * 1000.0), 0)
    depth = numpy.clip(depth, 0, 65535).astype(numpy.uint16)
    rgb = None
    packed = "rgb" if "rgb" in columns else "rgba" if "rgba" in columns else None
    if packed:
        v = numpy.frombuffer(columns[packed], dtype="<u4").reshape(height, width)
        rgb = numpy.stack([(v >> 16) & 255, (v >> 8) & 255, v & 255], axis=2).astype(numpy.uint8)
    return depth, rgb


def read_tum(blob, name):
    v = depth_frames.decode_depth(blob, name).astype(numpy.uint32)
    return ((v + 2) // 5).astype(numpy.uint16)  # round(v / 5) for integers


def read_png_rgb(blob):
    width, height, rows, _ = png.Reader(file=io.BytesIO(blob)).asRGB8()
    return numpy.vstack([numpy.asarray(r, dtype=numpy.uint8) for r in rows]).reshape(height, width, 3)


CONVERSIONS = {
    ".pcd": "depth_mm = round(z * 1000) of the organised cloud, 0 where z is NaN; colour from the packed rgb field",
    ".png": "TUM depth (5000 a metre): depth_mm = round(value / 5)",
    ".bag": "depth_mm = round(1000 * m) of the bag's 32FC1 depth_registered image (ties to even, 0 where m is NaN), "
            "as rdsf's bag source reads it; colour the bag's rgb8 image. The first bag is kept here as hall_1.bag",
}
DEFAULT_CAMERA = "- Camera: no camera.yml; the workbench's Kinect v1 model (fx = fy = 525, cx = 319.5, cy = 239.5)"


def readme(source, spec, written, camera_line):
    """written: per frame (has colour, stamp gap of the colour in ms or None)."""
    _, repo, commit, licence, licence_file, people, description, frames = spec
    kind = os.path.splitext(frames[0][1])[1]
    gaps = any(gap is not None for _, gap in written)
    lines = [f"# {source}", "", description + ".", "",
             f"- Source: https://github.com/{repo} @ {commit}",
             f"- Licence: {licence} (the text: {licence_file})",
             f"- People: {people}",
             "- Converted by scripts/public-frames.py: " + CONVERSIONS[kind],
             camera_line,
             "", "| frame | path at the commit | what it shows | colour |" + (" colour stamp - depth stamp |" if gaps else ""),
             "| --- | --- | --- | --- |" + (" --- |" if gaps else "")]
    for (name, path, what), (colour, gap) in zip(frames, written):
        lines.append(f"| {name} | {path} | {what} | {'yes' if colour else 'no'} |" +
                     (f" {gap:+.0f} ms |" if gaps else ""))
    return "\n".join(lines) + "\n"


def read_bag(blob, name):
    """A bag of one registered RGB-D frame as (depth_mm, rgb, camera model dict, colour - depth stamp in ms)."""
    import tempfile
    try:
        import rosbag
    except ImportError as e:
        raise SourceError(f"{name}: reading bags needs python3-rosbag ({e})")
    with tempfile.NamedTemporaryFile(suffix=".bag") as f:
        f.write(blob)
        f.flush()
        messages = {}
        for topic, message, _ in rosbag.Bag(f.name).read_messages():
            messages.setdefault(topic.rsplit("/", 2)[-2] + "/" + topic.rsplit("/", 1)[-1], message)
    depth, colour, info = (messages.get(k) for k in ("depth_registered/image", "rgb/image_raw", "rgb/camera_info"))
    if depth is None or depth.encoding != "32FC1" or colour is None or colour.encoding != "rgb8" or info is None:
        raise SourceError(f"{name}: not one 32FC1 depth_registered image, one rgb8 image and their CameraInfo")
    m = numpy.frombuffer(depth.data, dtype="<f4").reshape(depth.height, depth.step // 4)[:, :depth.width]
    m = m.astype(numpy.float64)
    mm = numpy.where(numpy.isfinite(m), numpy.rint(1000.0 * numpy.nan_to_num(m)), 0)
    depth_mm = numpy.where((mm > 0) & (mm <= 65535), mm, 0).astype(numpy.uint16)
    rgb = numpy.frombuffer(colour.data, dtype=numpy.uint8).reshape(colour.height, colour.step)[:, :3 * colour.width]
    rgb = rgb.reshape(colour.height, colour.width, 3)
    camera = {"width": info.width, "height": info.height, "fx": info.K[0], "fy": info.K[4], "cx": info.K[2],
              "cy": info.K[5], "frame": info.header.frame_id, "distortion": (info.distortion_model, tuple(info.D))}
    gap_ms = (colour.header.stamp.to_sec() - depth.header.stamp.to_sec()) * 1000.0
    return depth_mm, rgb, camera, gap_ms


def camera_yml(camera):
    return ("%YAML:1.0\n---\nformat: rdsf-camera\nformat_version: 1\n"
            f"width_px: {camera['width']}\nheight_px: {camera['height']}\n"
            f"fx_px: {camera['fx']!r}\nfy_px: {camera['fy']!r}\ncx_px: {camera['cx']!r}\ncy_px: {camera['cy']!r}\n"
            "depth_unit_mm: 1\n")


def convert(out, repos):
    for source, spec in SOURCES.items():
        option, repo, commit, _, licence_file, _, _, frames = spec
        gitdir = repos[option]
        folder = os.path.join(out, source)
        os.makedirs(folder, exist_ok=True)
        written = []
        camera = None
        for index, (name, path, _) in enumerate(frames):
            blob = git_blob(gitdir, commit, path)
            where = f"{repo}:{path}"
            gap = None
            if path.endswith(".pcd"):
                depth, rgb = read_pcd(blob, where)
            elif path.endswith(".bag"):
                depth, rgb, frame_camera, gap = read_bag(blob, where)
                if camera is not None and frame_camera != camera:
                    raise SourceError(f"{where}: its CameraInfo differs from the first bag's")
                camera = frame_camera
                if index == 0:
                    depth_frames.write_bytes(os.path.join(folder, f"{name}.bag"), blob)
            else:
                depth = read_tum(blob, where)
                rgb = read_png_rgb(git_blob(gitdir, commit, path.replace("TUM_depth", "TUM_color")))
            depth_frames.write_png(os.path.join(folder, f"{name}.depth.png"), depth)
            if rgb is not None:
                depth_frames.write_png(os.path.join(folder, f"{name}.rgb.png"), rgb)
            written.append((rgb is not None, gap))
            valid = depth[depth > 0]
            print(f"{source}/{name}: {depth.shape[1]}x{depth.shape[0]}, {valid.size} readings, "
                  f"median {int(numpy.median(valid)) if valid.size else 0} mm", file=sys.stderr)
        boxes = [(name, k + 1, box) for name, _, _ in frames for k, box in enumerate(BOXES.get(name, []))]
        if boxes:
            visible = any(len(box) == 5 for _, _, box in boxes)
            header = "frame,person,x,y,w,h" + (",visible_fraction" if visible else "") + "\n"
            depth_frames.write_text(os.path.join(folder, "boxes.csv"),
                                    header + "".join(f"{name},{k}," + ",".join(str(v) for v in box) + "\n"
                                                     for name, k, box in boxes))
        if option == "tue":
            depth_frames.write_text(os.path.join(folder, licence_file), MIT_TEXT)
        else:
            depth_frames.write_text(os.path.join(folder, licence_file), git_blob(gitdir, commit, licence_file).decode())
        camera_line = DEFAULT_CAMERA
        if camera is not None:
            depth_frames.write_text(os.path.join(folder, "camera.yml"), camera_yml(camera))
            camera_line = (f"- Camera: camera.yml from the colour camera's CameraInfo (K; frame {camera['frame']}, which "
                           "the registered depth shares); its distortion (" + camera["distortion"][0] + " " +
                           ", ".join(f"{d:.3g}" for d in camera["distortion"][1]) +
                           ") is not undone: the workbench's camera model is a pinhole")
        depth_frames.write_text(os.path.join(folder, "README.md"), readme(source, spec, written, camera_line))


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[1], usage=__doc__.split("\n")[0])
    p.add_argument("out")
    p.add_argument("--pcl", required=True, help="git folder of PointCloudLibrary/pcl")
    p.add_argument("--pcl-data", required=True, help="git folder of PointCloudLibrary/data")
    p.add_argument("--open3d", required=True, help="git folder of Acidburn0zzz/Open3D (a fork keeping TUM_depth.png)")
    p.add_argument("--tue", required=True, help="git folder of tue-robotics/people_recognition (its test bags)")
    a = p.parse_args()
    try:
        convert(a.out, {"pcl": a.pcl, "pcl_data": a.pcl_data, "open3d": a.open3d, "tue": a.tue})
    except (SourceError, depth_frames.FrameError, png.Error, ValueError, KeyError, OSError) as e:
        print(f"public-frames.py: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
