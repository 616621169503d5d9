#!/usr/bin/env python3
"""public-frames.py OUT --pcl GITDIR --pcl-data GITDIR --open3d GITDIR

Converts the public real depth frames of datasets/public/ (datasets/public/README.md) from the git
repositories they were found in (as the search tool's fetch brings them: bare git folders), at the commits
recorded there, into OUT/<SOURCE>/: NAME.depth.png (16-bit, millimetres, 0 = no reading), NAME.rgb.png when
the source has colour, boxes.csv where people are labelled, README.md (source, commit, path, licence, people) and the licence text. Nothing is
downloaded; the same repositories give the same bytes.

Conversions:
  organised PCD clouds (640x480, Kinect-class): depth_mm = round(z * 1000), 0 where z is NaN; colour from
    the packed rgb / rgba field. binary_compressed data is LZF (decompressed here) stored field by field.
  TUM RGB-D depth PNGs: 5000 units a metre, depth_mm = round(value / 5).

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

# The people of pcl_people's frame, drawn by hand (x, y, w, h in pixels), left to right.
BOXES = {"five_people": [(20, 68, 138, 408), (143, 98, 103, 378), (279, 103, 94, 337), (362, 103, 108, 347),
                         (470, 50, 136, 426)]}

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


def readme(source, spec, written):
    _, repo, commit, licence, licence_file, people, description, frames = spec
    lines = [f"# {source}", "", description + ".", "",
             f"- Source: https://github.com/{repo} @ {commit}",
             f"- Licence: {licence} (the text: {licence_file})",
             f"- People: {people}",
             "- Converted by scripts/public-frames.py: " +
             ("depth_mm = round(z * 1000) of the organised cloud, 0 where z is NaN; colour from the packed rgb field"
              if frames[0][1].endswith(".pcd") else "TUM depth (5000 a metre): depth_mm = round(value / 5)"),
             "- Camera: no camera.yml; the workbench's Kinect v1 model (fx = fy = 525, cx = 319.5, cy = 239.5)",
             "", "| frame | path at the commit | what it shows | colour |", "| --- | --- | --- | --- |"]
    for (name, path, what), colour in zip(frames, written):
        lines.append(f"| {name} | {path} | {what} | {'yes' if colour else 'no'} |")
    return "\n".join(lines) + "\n"


def convert(out, repos):
    for source, spec in SOURCES.items():
        option, repo, commit, _, licence_file, _, _, frames = spec
        gitdir = repos[option]
        folder = os.path.join(out, source)
        os.makedirs(folder, exist_ok=True)
        written = []
        for name, path, _ in frames:
            blob = git_blob(gitdir, commit, path)
            where = f"{repo}:{path}"
            if path.endswith(".pcd"):
                depth, rgb = read_pcd(blob, where)
            else:
                depth = read_tum(blob, where)
                rgb = read_png_rgb(git_blob(gitdir, commit, path.replace("TUM_depth", "TUM_color")))
            depth_frames.write_png(os.path.join(folder, f"{name}.depth.png"), depth)
            if rgb is not None:
                depth_frames.write_png(os.path.join(folder, f"{name}.rgb.png"), rgb)
            written.append(rgb is not None)
            valid = depth[depth > 0]
            print(f"{source}/{name}: {depth.shape[1]}x{depth.shape[0]}, {valid.size} readings, "
                  f"median {int(numpy.median(valid)) if valid.size else 0} mm", file=sys.stderr)
        boxes = [f"{name},{k + 1},{x},{y},{w},{h}\n" for name, _, _ in frames
                 for k, (x, y, w, h) in enumerate(BOXES.get(name, []))]
        if boxes:
            depth_frames.write_text(os.path.join(folder, "boxes.csv"), "frame,person,x,y,w,h\n" + "".join(boxes))
        depth_frames.write_text(os.path.join(folder, licence_file), git_blob(gitdir, commit, licence_file).decode())
        depth_frames.write_text(os.path.join(folder, "README.md"), readme(source, spec, written))


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[1], usage=__doc__.split("\n")[0])
    p.add_argument("out")
    p.add_argument("--pcl", required=True, help="git folder of PointCloudLibrary/pcl")
    p.add_argument("--pcl-data", required=True, help="git folder of PointCloudLibrary/data")
    p.add_argument("--open3d", required=True, help="git folder of Acidburn0zzz/Open3D (a fork keeping TUM_depth.png)")
    a = p.parse_args()
    try:
        convert(a.out, {"pcl": a.pcl, "pcl_data": a.pcl_data, "open3d": a.open3d})
    except (SourceError, depth_frames.FrameError, png.Error, ValueError, KeyError, OSError) as e:
        print(f"public-frames.py: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
