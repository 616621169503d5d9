"""What the Python helpers of scripts/ share about frames and boxes: one reader of depth PNGs (files or
bytes), one synced writer of PNGs (and of text and bytes), one IoU.

Uses Debian's python3-numpy and python3-png (scripts/setup.sh installs them).
"""
import os

import numpy
import png


class FrameError(Exception):
    """A frame that cannot be read as depth: the message names the file and the problem."""


def read_depth(path):
    """The 16-bit one-channel PNG at `path` as a uint16 array (height x width), millimetres."""
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as e:
        raise FrameError(f"{path}: {e}") from e
    return decode_depth(data, path)


def decode_depth(data, name):
    """The bytes of a 16-bit one-channel PNG as a uint16 array (height x width); `name` is used in messages."""
    try:
        width, height, rows, info = png.Reader(bytes=data).read()
        if info.get("bitdepth") != 16 or info.get("planes") != 1:
            raise FrameError(f"{name}: not a 16-bit one-channel depth PNG")
        return numpy.vstack([numpy.asarray(r, dtype=numpy.uint16) for r in rows]).reshape(height, width)
    except png.Error as e:
        raise FrameError(f"{name}: {e}") from e


def write_png(path, image):
    """`image` (uint8 or uint16; height x width for grey, height x width x 3 for colour) as a PNG of that bit
    depth: written to a temporary name, synced and renamed, so that a killed run never leaves half a picture
    under `path`."""
    bitdepth = 16 if image.dtype == numpy.uint16 else 8
    colour = image.ndim == 3
    rows = image.reshape(image.shape[0], -1).tolist()
    _write_synced(path, lambda out: png.Writer(width=image.shape[1], height=image.shape[0], greyscale=not colour,
                                               bitdepth=bitdepth).write(out, rows))


def write_text(path, text):
    """`text` to `path` through a temporary name, synced and renamed."""
    _write_synced(path, lambda out: out.write(text.encode()))


def write_bytes(path, data):
    """`data` to `path` through a temporary name, synced and renamed."""
    _write_synced(path, lambda out: out.write(data))


def _write_synced(path, write):
    tmp = path + ".tmp"
    with open(tmp, "wb") as out:
        write(out)
        out.flush()
        os.fsync(out.fileno())
    os.replace(tmp, path)


def iou(a, b):
    """Intersection over union of two boxes (x, y, w, h) in pixels; 0 when both are empty."""
    ix = max(0, min(a[0] + a[2], b[0] + b[2]) - max(a[0], b[0]))
    iy = max(0, min(a[1] + a[3], b[1] + b[3]) - max(a[1], b[1]))
    inter = ix * iy
    union = a[2] * a[3] + b[2] * b[3] - inter
    return inter / union if union > 0 else 0.0
