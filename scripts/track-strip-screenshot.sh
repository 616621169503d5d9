#!/usr/bin/env bash
# The picture of docs/adapting-to-your-room.md: rdsf-label --per-track's window (the asked candidate and the
# strip of its track) on a synthetic room, under Xvfb, dumped with xwd and converted to PNG. rdsf-synth options
# after OUT.png replace the room's "--people 2..2 --seed 31": docs/adapt-place-strip.png is made with
# "--people 1..1 --seed 31 --moving-camera 0 --empty" (a still camera, no people: the strip of the question's
# place, one answer per place, is shown under its track's).
# Usage: scripts/track-strip-screenshot.sh OUT.png [RDSF-SYNTH OPTION...]   (needs xvfb-run, xdotool, xwd, python3)
set -euo pipefail
cd "$(dirname "$0")/.."
usage="Usage: scripts/track-strip-screenshot.sh OUT.png [RDSF-SYNTH OPTION...]
  OUT.png   the picture to write (rdsf-label --per-track's window, cropped)
  options   the room's rdsf-synth options (default: --people 2..2 --seed 31, docs/adapt-track-strip.png)
Needs xvfb-run, xdotool, xwd and python3, and rdsf-synth and rdsf-label built (\$RDSF_BUILD_DIR, default build)."
case "${1:-}" in
  --help|-h) echo "$usage"; exit 0 ;;
  *.png) ;;
  *) echo "track-strip-screenshot: the first argument is the picture to write, OUT.png, not '${1:-}'" >&2; exit 2 ;;
esac
png=$(realpath -m "$1")
shift
bin=${RDSF_BUILD_DIR:-build}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
room=(--people 2..2 --seed 31)  # the room of docs/adapt-track-strip.png; options given replace these
[ $# -eq 0 ] || room=("$@")
"$bin/synth/rdsf-synth" --out "$work/room" --frames 60 --clip-frames 60 --rgb "${room[@]}" >/dev/null 2>&1
xvfb-run -a -s "-screen 0 1200x1000x24" bash -c '
  "$0/labeler/rdsf-label" --source "$1/room" --out "$1/set" --model people --ask uncertain --per-track \
    --keep-rejected --threads 2 2>"$1/label.log" &
  labeler=$!
  id=$(timeout 60 xdotool search --sync --onlyvisible --name "^rdsf-label$" | head -1)
  for ((i = 0; i < 120; ++i)); do grep -q "scored 60" "$1/label.log" 2>/dev/null && break; sleep 0.5; done
  sleep "${2:-3}"
  xwd -root -silent -out "$1/screen.xwd"
  xdotool key --window "$id" q
  for ((i = 0; i < 20; ++i)); do kill -0 $labeler 2>/dev/null || break; sleep 0.5; done
  kill $labeler 2>/dev/null || true
' "$bin" "$work"
# XWD (ZPixmap, 32 bits per pixel) to PNG, cropped to the window (what is not the root's black), with Python's zlib.
python3 - "$work/screen.xwd" "$png" <<'PY'
import struct, sys, zlib
data = open(sys.argv[1], 'rb').read()
h = struct.unpack('>25I', data[:100])
header_size, width, height, order, bpp, bpl, ncolors = h[0], h[4], h[5], h[7], h[11] // 8, h[12], h[19]
pixels = data[header_size + ncolors * 12:]
rows = [pixels[y * bpl:y * bpl + width * bpp] for y in range(height)]
def rgb(row, x):  # LSBFirst: B G R (X); MSBFirst: (X) R G B
    p = row[bpp * x:bpp * x + bpp]
    return (p[2], p[1], p[0]) if order == 0 else (p[-3], p[-2], p[-1])
def lit(row, x): return any(rgb(row, x))
ys = [y for y in range(height) if any(lit(rows[y], x) for x in range(0, width, 7))]
xs = [x for x in range(width) if any(lit(rows[y], x) for y in ys[::7])]
x0, x1, y0, y1 = min(xs), max(xs) + 1, min(ys), max(ys) + 1
raw = b''.join(b'\0' + bytes(c for x in range(x0, x1) for c in rgb(r, x))
               for r in rows[y0:y1])
def chunk(kind, body): return struct.pack('>I', len(body)) + kind + body + struct.pack('>I', zlib.crc32(kind + body))
png = b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', x1 - x0, y1 - y0, 8, 2, 0, 0, 0))
png += chunk(b'IDAT', zlib.compress(raw, 9)) + chunk(b'IEND', b'')
open(sys.argv[2], 'wb').write(png)
PY
echo "wrote $png"
