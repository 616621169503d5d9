#!/usr/bin/env bash
# CTest slurm_mine_array (issue 37): scripts/slurm/mine-array.sbatch on a real Slurm. Starts a private
# munged, slurmctld and slurmd (one node: this machine, 2 processors) in a temporary folder on ports 16817-16818,
# renders three short people-free recordings, submits the array (--array=1-3) and the merge (afterok), and
# checks the merged set has exactly the rows of one rdsf-mine over the recordings (sorted sample lines
# without id and time). Stops its daemons by their pid files. Exit 77 (CTest: skipped) when slurm-wlm or
# munge is not installed, or when not root (slurmd runs jobs as their user).
set -euo pipefail
cd "$(dirname "$0")/.."
skip() { echo "slurm_mine_array: skipped: $*"; exit 77; }
for p in slurmctld slurmd sbatch munged; do command -v "$p" >/dev/null || PATH=$PATH:/usr/sbin; command -v "$p" >/dev/null || skip "$p is not installed (Debian: slurm-wlm)"; done
[ "$(id -u)" -eq 0 ] || skip "a private slurmd needs root"
[ -r /etc/munge/munge.key ] || skip "/etc/munge/munge.key is absent (Debian: munge)"
bin=$(cd "${RDSF_BUILD_DIR:-build}" && pwd)
tmp=$(mktemp -d /tmp/rdsf-slurm.XXXXXX)
mkdir -p "$tmp"/{state,spool,log,run}
stop() {
  for p in slurmd slurmctld munged; do [ -f "$tmp/run/$p.pid" ] && kill "$(cat "$tmp/run/$p.pid")" 2>/dev/null || true; done
  sleep 1
  rm -rf "$tmp"
}
trap stop EXIT
host=$(hostname -s)
cat >"$tmp/slurm.conf" <<CONF
ClusterName=rdsftest
SlurmctldHost=$host
AuthType=auth/munge
AuthInfo=socket=$tmp/run/munge.sock
SlurmUser=root
SlurmctldPort=16817
SlurmdPort=16818
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/run/slurmctld.pid
SlurmdPidFile=$tmp/run/slurmd.pid
SlurmctldLogFile=$tmp/log/slurmctld.log
SlurmdLogFile=$tmp/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
MpiDefault=none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
NodeName=$host CPUs=2 State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=10 State=UP
CONF
export SLURM_CONF=$tmp/slurm.conf
munged --socket="$tmp/run/munge.sock" --pid-file="$tmp/run/munged.pid" --log-file="$tmp/log/munged.log" \
  --seed-file="$tmp/run/munge.seed" -f
slurmctld -f "$SLURM_CONF"
slurmd -f "$SLURM_CONF"
for i in $(seq 50); do sinfo -h -o %T 2>/dev/null | grep -q idle && break; sleep 0.2; done
sinfo -h -o %T | grep -q idle || { tail -5 "$tmp/log/"*.log; echo "slurm_mine_array: the private Slurm did not start" >&2; exit 1; }

for k in 1 2 3; do
  "$bin/synth/rdsf-synth" --out "$tmp/rec$k" --frames $((4 + k)) --seed "$k" --empty --clip-frames 4 >/dev/null 2>&1
  echo "$tmp/rec$k" >>"$tmp/list.txt"
done
"$bin/miner/rdsf-mine" --source "$tmp"/rec1 "$tmp"/rec2 "$tmp"/rec3 --out "$tmp/whole" --threads 1 2>/dev/null
export RDSF_BUILD_DIR=$bin
job=$(sbatch --parsable --export=ALL --output="$tmp/log/task-%a.log" --array=1-3 scripts/slurm/mine-array.sbatch \
  "$tmp/list.txt" "$tmp/merged" -- --threads 1)
sbatch --parsable --export=ALL --output="$tmp/log/merge.log" --dependency="afterok:$job" \
  scripts/slurm/mine-array.sbatch --merge "$tmp/list.txt" "$tmp/merged" >/dev/null
for i in $(seq 600); do [ -z "$(squeue -h)" ] && break; sleep 0.2; done
[ -z "$(squeue -h)" ] || { echo "slurm_mine_array: the jobs did not finish in 120 s" >&2; squeue; exit 1; }
cat "$tmp/log/merge.log"
rows() { tail -n +2 "$1/samples.tsv" | cut -f2-16,18- | sort; }  # without the id (1) and time (17)
n=$(rows "$tmp/whole" | wc -l)
[ "$n" -gt 10 ] || { echo "slurm_mine_array: the unsharded run found only $n samples" >&2; exit 1; }
if ! diff <(rows "$tmp/whole") <(rows "$tmp/merged") >"$tmp/diff"; then
  echo "slurm_mine_array: the merged set differs from one rdsf-mine run:" >&2; head "$tmp/diff" >&2; exit 1
fi
for k in 1 2 3; do grep -q "shard $k/3" "$tmp/log/task-$k.log" || { echo "slurm_mine_array: task $k did not mine shard $k/3" >&2; cat "$tmp/log/task-$k.log" >&2; exit 1; }; done
echo "slurm_mine_array: 3 array tasks and the merge gave the $n samples of one run"
