#!/usr/bin/env bash
# The scripts' command lines (CTest report_scripts): scripts/lib/options.sh, the one reader they share,
# takes values, switches, -- and pass-through as its header says and refuses the rest; every script's
# --help exits 0 and names its defaults, an unknown argument is a usage error (exit 2), a folder without a
# quality report's data is a one-line error naming the folder (exit 1), all before any work.
set -uo pipefail
cd "$(dirname "$0")/.."
fail() { echo "check-report-scripts: $*" >&2; exit 1; }
expect() {  # exit code, pattern of stderr/stdout, command...
  local code=$1 pattern=$2; shift 2
  local output status
  output=$("$@" 2>&1); status=$?
  [ "$status" -eq "$code" ] || fail "$* exited $status, expected $code: $output"
  grep -qE -e "$pattern" <<<"$output" || fail "$* printed no line matching '$pattern': $output"
}
empty=$(mktemp -d); trap 'rm -rf "$empty"' EXIT

# options_of ARGS...: what script_options makes of ARGS with a fixed set of specs, as one line.
options_of() {
  bash -c '. scripts/lib/options.sh
    usage() { echo "usage: demo"; }
    out=out/default real=../real docs=0 peer=1
    script_options demo --out=out --real=real --no-real=real= --docs=docs=1 --no-peer=peer=0 "$PASS" -- "$@"
    echo "out=$out real=$real docs=$docs peer=$peer rest=${script_rest[*]}"' demo "$@"
}
PASS= expect 0 "^out=out/default real=../real docs=0 peer=1 rest=$" options_of
PASS= expect 0 "^out=a b real= docs=1 peer=0 rest=$" options_of --out "a b" --no-real --docs --no-peer
PASS= expect 0 "^out=x=y real=r docs=0 peer=1 rest=$" options_of --out=x=y --real r
PASS= expect 0 "^out=2 real=../real docs=0 peer=1 rest=--out 3 -v$" options_of --out 1 --out 2 -- --out 3 -v
PASS= expect 0 "^usage: demo$" options_of --docs --help
PASS= expect 2 "^demo: unknown argument '--bogus'$" options_of --docs --bogus
PASS= expect 2 "^demo: unknown argument 'stray'$" options_of stray
PASS= expect 2 "^demo: --out needs a value$" options_of --docs --out
PASS= expect 2 "^demo: --docs takes no value$" options_of --docs=1
PASS='*' expect 0 "^out=o real=../real docs=0 peer=1 rest=--quick --rounds 3$" options_of --quick --out o --rounds 3
PASS= expect 2 "^usage: demo$" options_of --bogus

scripts=(quality-report regularisation-sweep adaptation-benchmark loso-report background-report propagation-report
         resolution-report main-job train-default-model shard-mine feature-spec-compare labeler-bench
         scaling-measure ros-latency option-reference candidate-recipe-report)
for s in "${scripts[@]}"; do
  expect 0 "[Dd]efault" "scripts/$s.sh" --help
  expect 2 "unknown argument '--bogus'" "scripts/$s.sh" --bogus
done
# The scripts that take targets or a file first: --help too, and a wrong first argument is a usage error.
expect 0 "FUZZ_SECONDS" scripts/fuzz.sh --help
expect 0 "[Dd]efault" scripts/track-strip-screenshot.sh --help
expect 2 "the first argument is the picture to write" scripts/track-strip-screenshot.sh --bogus
expect 2 "no fuzz target 'bogus'" scripts/fuzz.sh bogus
# Every script that reads options reads them with scripts/lib/options.sh (perf-report passes the rest on).
for f in scripts/*.sh; do
  grep -qE '^while (\(\(\$#\)\)|\[ \$# -gt 0 \]); do' "$f" &&
    fail "$f reads its options with a loop of its own: use script_options (scripts/lib/options.sh)"
done
expect 2 "--test-frames takes a positive number" scripts/quality-report.sh --test-frames 0
expect 2 "--synthetic takes 0-16" scripts/adaptation-benchmark.sh --synthetic 17
expect 2 "--camera takes rdsf-synth's --size WxH and --fov HxV, not '--rgb'" scripts/adaptation-benchmark.sh --camera "--size 512x424 --rgb"
expect 2 "--seed takes a whole number" scripts/adaptation-benchmark.sh --seed x1
expect 2 "--people-distance takes MIN..MAX in metres" scripts/adaptation-benchmark.sh --people-distance 2.5
expect 0 "default track" scripts/adaptation-compare.py --help
expect 2 "adaptation-compare: /nonexistent/results.tsv: No such file" scripts/adaptation-compare.py /nonexistent
expect 2 "give one run, or two to compare" scripts/adaptation-compare.py a b c
# A run of two rooms: people found = TAR x people, and lost = what the model as given found that adapting lost.
run=$(mktemp -d); trap 'rm -rf "$empty" "$run"' EXIT
mkdir -p "$run/rooms/lab/report-people" "$run/rooms/synthetic-1/report-people" "$run/rooms/synthetic-1/track-50"
printf 'room\tmode\tbudget\tanswers\tpropagated\tpropagated_wrong\ttar\ttrain_s\n%s\n%s\n%s\n%s\n' \
  $'lab\tnone\t0\t0\t0\t0\t1.000\t0' $'lab\ttrack\t50\t20\t5\t0\t0.750\t1.0' \
  $'synthetic-1\tnone\t0\t0\t0\t0\t0.500\t0' $'synthetic-1\ttrack\t50\t30\t9\t0\t0.900\t1.0' > "$run/results.tsv"
echo "Model people v4: 12 frames, 12 people, 0 segmentation errors" > "$run/rooms/lab/report-people/summary.txt"
echo "Model people v4: 30 frames, 30 people, 0 segmentation errors" > "$run/rooms/synthetic-1/report-people/summary.txt"
printf 'switch.hole-gap\ton\nswitch.border-height\toff\n' > "$run/rooms/synthetic-1/track-50/adapt-state.tsv"
expect 0 '^\| synthetic-1 \| 30 \| 15 \| 27 \[hole-gap\] \|$' scripts/adaptation-compare.py "$run"
expect 0 '^\| real: 1 rooms \| 12 \| 12 \| \*\*9\*\* \(lost 3\) \|$' scripts/adaptation-compare.py "$run"
expect 2 "--frames takes a positive number" scripts/propagation-report.sh --frames 0
expect 2 "--seeds takes numbers" scripts/propagation-report.sh --seeds "31 x"
expect 2 "--docs needs the whole report" scripts/quality-report.sh --docs --only levers
expect 2 "--only takes levers, recipes or shipped" scripts/quality-report.sh --only bogus
expect 2 "--docs needs the whole report" scripts/quality-report.sh --docs --only shipped
expect 2 "--people-version takes 2, 3 or 4" scripts/train-default-model.sh --people-version 5
expect 2 "--cameras takes kinect1 or mix" scripts/train-default-model.sh --cameras bogus
expect 2 "--seed takes a whole number" scripts/train-default-model.sh --seed x
expect 2 "--seed 2 models are not for --install" scripts/train-default-model.sh --seed 2 --install
expect 1 "^train-default-model: $empty/sets holds no people and negatives sets" scripts/train-default-model.sh --sets-from "$empty"
expect 2 "--seeds takes numbers" scripts/candidate-recipe-report.sh --seeds "1 x"
expect 2 "^loso-report: --judges '31 x': 'x' is not a seed" scripts/loso-report.sh --judges "31 x"
expect 2 "^loso-report: --judges is empty" scripts/loso-report.sh --judges ""
expect 2 "unknown set 'bogus'" scripts/candidate-recipe-report.sh --sets "lab bogus"
expect 2 "--people-version takes 2, 3 or 4" scripts/candidate-recipe-report.sh --people-version 5
expect 2 "a recipe is NAME=OPTIONS, not 'v3'" scripts/candidate-recipe-report.sh --recipes "v3"
expect 1 "^candidate-recipe-report: $empty holds no train/ and empty/ renderings" scripts/candidate-recipe-report.sh --data "$empty" --out "$empty/o"
expect 2 "--cameras mix models are not for --install" scripts/train-default-model.sh --cameras mix --install
expect 2 "--near-people takes --people-version 4's recipe" scripts/train-default-model.sh --near-people --people-version 3
expect 2 "--near-people renders through the Kinect v1 only" scripts/train-default-model.sh --near-people --cameras mix
expect 2 "--near-people models are not for --install" scripts/train-default-model.sh --near-people --install
expect 1 "^regularisation-sweep: $empty has no quality report's data" scripts/regularisation-sweep.sh --out "$empty"
[ -z "$(ls -A "$empty")" ] || fail "regularisation-sweep wrote into $empty although it refused it"
# candidate-crops.py: its help, a usage error before any work, and a picture of one row from a frame of its own.
expect 0 "ROW is CSV:FRAMES:KIND:N" /usr/bin/python3 scripts/candidate-crops.py --help
expect 2 "^candidate-crops: row 'a:b:bad:3': KIND is one of top-clutter, top-pieces, people, not 'bad'$" \
  /usr/bin/python3 scripts/candidate-crops.py "$empty/x.png" a:b:bad:3
expect 2 "^candidate-crops: row 'a:b:people:3': people needs a TRUTH file$" \
  /usr/bin/python3 scripts/candidate-crops.py "$empty/x.png" a:b:people:3
expect 2 "^candidate-crops: row 'a:b:bad:3': KIND is one of" \
  /usr/bin/python3 scripts/candidate-crops.py "$empty/x.png" "$empty/none.csv:$empty:top-clutter:2" a:b:bad:3
[ ! -e "$empty/x.png" ] || fail "candidate-crops wrote a picture although it refused its arguments"
/usr/bin/python3 -c 'import png, sys
png.Writer(width=40, height=30, greyscale=True, bitdepth=16).write(open(sys.argv[1], "wb"), [[1000 + 10 * x for x in range(40)]] * 30)' \
  "$empty/f.depth.png" || fail "could not write a test frame"
printf 'frame,candidate,x,y,w,h,depth_mm,score,person,distance_cm\nf,0,5,5,10,20,1100,1.5,1,0\nf,1,20,2,8,16,1300,-0.5,0,0\n' >"$empty/c.csv"
expect 0 "^top-clutter of $empty/c.csv: H 1.50 -0.50$" \
  /usr/bin/python3 scripts/candidate-crops.py "$empty/crops.png" "$empty/c.csv:$empty:top-clutter:5"
/usr/bin/python3 -c 'import png, sys; w, h, _, _ = png.Reader(filename=sys.argv[1]).read(); sys.exit(0 if (w, h) == (272, 256) else 1)' \
  "$empty/crops.png" || fail "candidate-crops' picture is not two 64x128 tiles at twice their size"
rm -f "$empty/f.depth.png" "$empty/c.csv" "$empty/crops.png"

# public-frames.py: its help, a usage error, a repository it cannot read (one line naming it, exit 1), its LZF
# decoder on a literal run and an overlapping back reference, and the frames it made being the ones checked in.
expect 0 "--pcl-data GITDIR" /usr/bin/python3 scripts/public-frames.py --help
expect 2 "required" /usr/bin/python3 scripts/public-frames.py "$empty/p"
expect 1 "^public-frames.py: $empty/none: cannot read " \
  /usr/bin/python3 scripts/public-frames.py "$empty/p" --pcl "$empty/none" --pcl-data "$empty/none" --open3d "$empty/none" \
    --tue "$empty/none"
expect 0 "^b'abcabcabc'$" /usr/bin/python3 -c 'import importlib.util as u
s = u.spec_from_file_location("pf", "scripts/public-frames.py"); m = u.module_from_spec(s); s.loader.exec_module(m)
print(m.lzf_decompress(bytes([2, 97, 98, 99, 4 << 5, 2]), 9))'
expect 1 "LZF data gives 3 bytes" /usr/bin/python3 -c 'import importlib.util as u
s = u.spec_from_file_location("pf", "scripts/public-frames.py"); m = u.module_from_spec(s); s.loader.exec_module(m)
m.lzf_decompress(bytes([2, 97, 98, 99]), 9)'
# paired-clips.py: its help, usage errors, clips that do not match (one line naming the file, exit 1), and the
# paired difference of two hand-made clips.csv: A finds 5 + 5 of 10 + 10 people, B 10 + 5, a third clip empty.
expect 0 "A:B \\[A:B \\.\\.\\.\\]" /usr/bin/python3 scripts/paired-clips.py --help
expect 2 "^paired-clips: 'x' is not A:B" /usr/bin/python3 scripts/paired-clips.py x
expect 2 "^paired-clips: unknown argument '--bogus'$" /usr/bin/python3 scripts/paired-clips.py --bogus "$empty/a:$empty/b"
mkdir -p "$empty/a" "$empty/b" "$empty/c"
header=model,clip_frames,probability,clip,frames,people,with_candidate,detected,false_positives
printf '%s\nm,60,0.5,#0,60,10,8,5,1\nm,60,0.5,#1,60,10,9,5,0\nm,60,0.5,#2,60,0,0,0,3\n' "$header" >"$empty/a/clips.csv"
printf '%s\nm,60,0.5,#0,60,10,10,10,1\nm,60,0.5,#1,60,10,9,5,0\nm,60,0.5,#2,60,0,0,0,0\n' "$header" >"$empty/b/clips.csv"
printf '%s\nm,60,0.5,#0,60,10,8,5,1\nm,60,0.5,#1,60,12,9,5,0\nm,60,0.5,#2,60,0,0,0,3\n' "$header" >"$empty/c/clips.csv"
expect 0 "^\\| TAR at the operating point \\| 0\\.500 \\| 0\\.750 \\| \\+0\\.250 \\(\\+0\\.000 to \\+0\\.500\\) \\|$" \
  /usr/bin/python3 scripts/paired-clips.py "$empty/a:$empty/b"
expect 0 "^\\| false positives per frame \\| 0\\.022 \\| 0\\.006 \\| -0\\.017 " /usr/bin/python3 scripts/paired-clips.py "$empty/a:$empty/b"
expect 0 "^## pooled over the 2 sets: 6 clips, 360 frames, 40 people" \
  /usr/bin/python3 scripts/paired-clips.py "$empty/a:$empty/b" "$empty/a:$empty/b"
expect 1 "^paired-clips: $empty/c/clips.csv: clip #1 has 60 frames and 12 people" \
  /usr/bin/python3 scripts/paired-clips.py "$empty/a:$empty/c"
expect 1 "^paired-clips: $empty/none/clips.csv: No such file" /usr/bin/python3 scripts/paired-clips.py "$empty/a:$empty/none"
cat "$empty/a/clips.csv" <(tail -n +2 "$empty/a/clips.csv") >"$empty/c/clips.csv"
expect 1 "^paired-clips: $empty/c/clips.csv: clip #0 of model 'm' is listed more than once" \
  /usr/bin/python3 scripts/paired-clips.py "$empty/a:$empty/c"
# With outcomes.csv in both reports, TAR at FPPF <= 0.1 from each exact curve: 30 frames allow 3 false positives;
# A's curve reaches 3 of 4 people within them, B's 4 of 4.
mkdir -p "$empty/d" "$empty/e"
printf '%s\nm,60,0.5,#0,10,2,2,1,0\nm,60,0.5,#1,10,2,2,1,1\nm,60,0.5,#2,10,0,0,0,1\n' "$header" | tee "$empty/d/clips.csv" >"$empty/e/clips.csv"
printf 'model,clip,score,outcome\nm,#0,3,detection\nm,#1,2,false_positive\nm,#0,1,detection\nm,#1,0.5,detection\nm,#2,0.4,false_positive\nm,#2,0.3,false_positive\nm,#1,0.1,false_positive\n' >"$empty/d/outcomes.csv"
printf 'model,clip,score,outcome\nm,#0,3,detection\nm,#0,2.5,detection\nm,#1,2,detection\nm,#1,1.9,detection\nm,#2,1,false_positive\nm,#1,0.7,neutral\n' >"$empty/e/outcomes.csv"
expect 0 "^\\| TAR at FPPF <= 0\\.1 \\| 0\\.750 \\| 1\\.000 \\| \\+0\\.250 " /usr/bin/python3 scripts/paired-clips.py "$empty/d:$empty/e"
expect 0 "no outcomes.csv in both reports" /usr/bin/python3 scripts/paired-clips.py "$empty/a:$empty/b"
# pooled: each set's TAR off its own curve, people found summed (two sets of 3 + 3 found of 4 + 4 in A)
expect 0 "^\\| TAR at FPPF <= 0\\.1 \\| 0\\.750 \\| 1\\.000 \\| \\+0\\.250 \\(\\+0\\.[0-9]+ to \\+0\\.[0-9]+\\) \\|$" \
  /usr/bin/python3 scripts/paired-clips.py "$empty/d:$empty/e" "$empty/d:$empty/e"
printf 'model,clip,score,outcome\nm,#7,3,detection\n' >"$empty/e/outcomes.csv"
expect 1 "^paired-clips: $empty/e/outcomes.csv: clip '#7' is not in clips.csv$" /usr/bin/python3 scripts/paired-clips.py "$empty/d:$empty/e"
rm -rf "$empty/a" "$empty/b" "$empty/c" "$empty/d" "$empty/e"
echo "check-report-scripts: ok"
