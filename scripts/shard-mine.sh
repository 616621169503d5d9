#!/usr/bin/env bash
# Mining at scale (issue 37): the people-free recordings of a list mined in N shards over GNU parallel (this
# machine's cores, or other machines with --sshlogin), each shard into its own sample set, then the existing
# merge (rdsf-mine --merge) into one set. Shard i of N is `rdsf-mine --source <every recording> --shard i/N`:
# every N-th strided frame of every recording, so the shards are even whatever the recordings' lengths, and
# the merged set holds exactly the samples of one rdsf-mine over the whole list (ids renumbered, order by
# shard). Everything resumes: a shard mined again skips what it has, the merge skips what the set has.
# Slurm runs the same per-shard step per array index: scripts/slurm/mine-array.sbatch.
set -euo pipefail
. "$(dirname "$0")/lib/options.sh"

usage() {
  cat <<USAGE
Usage: scripts/shard-mine.sh --list FILE --out SET [options] [-- rdsf-mine options...]
  --list FILE       recordings (frame sources), one per line; blank lines and # comments are skipped
  --out SET         the merged sample set (created, or appended to without duplicates)
  --shards N        shards (default: the cores of this machine, nproc)
  --work DIR        where the shard sets go (default SET.shards): DIR/shard-I of N
  --jobs J          shards at once per machine (GNU parallel -j; default: one per core)
  --sshlogin HOSTS  GNU parallel --sshlogin (e.g. ':,4/node1,node2'): the recordings, DIR and SET must be on a
                    file system all machines mount at the same path, rdsf-mine on their PATH or RDSF_MINE
  --one-shard I     mine shard I of --shards N only, no merge (what a Slurm array task runs)
  --merge-only      merge the shard sets of DIR into SET only
Options after -- go to every rdsf-mine (e.g. --model M --min-score 0 for hard negatives, --threads 1).
rdsf-mine: \$RDSF_MINE, else \$RDSF_BUILD_DIR/miner/rdsf-mine (default build/), else rdsf-mine on the PATH.
USAGE
}
list="" out="" shards="" work="" jobs="" sshlogin="" one="" merge_only=0 extra=()
script_options shard-mine --list=list --out=out --shards=shards --work=work --jobs=jobs --sshlogin=sshlogin --one-shard=one --merge-only=merge_only=1 -- "$@"
extra=("${script_rest[@]}")
[ -n "$out" ] || { echo "shard-mine: give --out SET" >&2; usage >&2; exit 2; }
shards=${shards:-$(nproc 2>/dev/null || echo 2)}
[[ "$shards" =~ ^[1-9][0-9]*$ ]] || { echo "shard-mine: --shards must be a positive number, not '$shards'" >&2; exit 2; }
[ -z "$one" ] || [[ "$one" =~ ^[1-9][0-9]*$ && "$one" -le "$shards" ]] ||
  { echo "shard-mine: --one-shard must be 1..$shards, not '$one'" >&2; exit 2; }
work=${work:-$out.shards}
mine=${RDSF_MINE:-}
if [ -z "$mine" ]; then
  mine="${RDSF_BUILD_DIR:-build}/miner/rdsf-mine"
  [ -x "$mine" ] && mine=$(cd "$(dirname "$mine")" && pwd)/rdsf-mine || mine=rdsf-mine
fi

merge() {
  local sets=() i
  for ((i = 1; i <= shards; i++)); do
    [ -d "$work/shard-$i" ] || { echo "shard-mine: $work/shard-$i is missing: mine shard $i of $shards first" >&2; exit 1; }
    sets+=("$work/shard-$i")
  done
  "$mine" --merge "${sets[@]}" --out "$out"
}
if ((merge_only)); then merge; exit 0; fi

[ -n "$list" ] || { echo "shard-mine: give --list FILE" >&2; usage >&2; exit 2; }
[ -r "$list" ] || { echo "shard-mine: $list: cannot read the list of recordings" >&2; exit 1; }
sources=()
while IFS= read -r line || [ -n "$line" ]; do
  line=${line%%#*}
  line=$(printf '%s' "$line" | sed 's/^[[:space:]]*//; s/[[:space:]]*$//')
  [ -n "$line" ] && sources+=("$line")
done <"$list"
((${#sources[@]})) || { echo "shard-mine: $list names no recording" >&2; exit 1; }
mkdir -p "$work"

if [ -n "$one" ]; then
  exec "$mine" --source "${sources[@]}" --out "$work/shard-$one" --shard "$one/$shards" "${extra[@]}"
fi
command -v parallel >/dev/null || { echo "shard-mine: GNU parallel is not installed (Debian: apt-get install parallel)" >&2; exit 1; }
# One job per shard; the first failure stops the others (they resume when run again).
popts=(--halt now,fail=1 --line-buffer --tag)
[ -n "$jobs" ] && popts+=(-j "$jobs")
[ -n "$sshlogin" ] && popts+=(--sshlogin "$sshlogin" --workdir "$PWD")
echo "shard-mine: ${#sources[@]} recording(s) in $shards shards into $work, then $out" >&2
# The command with every word quoted but parallel's {} (the shard number).
quoted="$(printf '%q ' "$mine" --source "${sources[@]}") --out $(printf '%q' "$work")/shard-{} --shard {}/$shards"
((${#extra[@]})) && quoted+=" $(printf '%q ' "${extra[@]}")"
# rdsf-mine's progress line is rewritten in place: keep only its summary lines in the tagged output.
parallel "${popts[@]}" "$quoted 2>&1 | tr '\r' '\n' | grep -v '^frames '" ::: $(seq "$shards")
merge
