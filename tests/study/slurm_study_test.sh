#!/usr/bin/env bash
# tools/slurm_study.sh on a real one-node Slurm cluster: starts munged, slurmctld and slurmd on
# this machine from a minimal slurm.conf in WORK_DIR, runs a small study as a 2-task job array
# with the merge after it, and checks that the merged study's combinations and answers equal an
# unsharded run's (records.jsonl without the times). Exit 77 (CTest: skipped) with the reason
# when Slurm is not installed or cannot start here.
#   slurm_study_test.sh COLLIDO SOURCE_DIR WORK_DIR
set -euo pipefail
collido=$(realpath "$1")
source_dir=$(realpath "$2")
work=$3

for tool in munged munge slurmctld slurmd sbatch sinfo; do
  if ! command -v "$tool" > /dev/null; then
    echo "SKIPPED: $tool is not installed (Debian: slurm-wlm, munge; tools/install_deps.sh --ci)"
    exit 77
  fi
done
if [[ $(id -u) -ne 0 ]]; then
  echo "SKIPPED: starting slurmd needs root (it runs the jobs as their users)"
  exit 77
fi

rm -rf "$work"
mkdir -p "$work"/{state,spool,log,munge}
work=$(realpath "$work")
chmod 700 "$work/munge"
socket=$work/munge/munge.sock
cleanup() {
  for pid_file in "$work/slurmd.pid" "$work/slurmctld.pid"; do
    [[ -f $pid_file ]] && kill "$(cat "$pid_file")" 2> /dev/null || true
  done
  munged --stop --socket="$socket" > /dev/null 2>&1 || true
}
trap cleanup EXIT

skip_with_log() {
  echo "SKIPPED: $1"
  tail -n 20 "$2" 2> /dev/null | sed 's/^/  /'
  exit 77
}

dd if=/dev/urandom of="$work/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$work/munge/munge.key"
# --force: munged refuses root without it; everything it needs is in this folder.
munged --force --socket="$socket" --key-file="$work/munge/munge.key" \
  --log-file="$work/log/munged.log" --pid-file="$work/munge/munged.pid" \
  --seed-file="$work/munge/munged.seed" ||
  skip_with_log "munged could not start" "$work/log/munged.log"
munge -S "$socket" -n | unmunge -S "$socket" > /dev/null ||
  skip_with_log "munge cannot encode and decode a credential" "$work/log/munged.log"

# Ports from this process's id, so that two runs on one machine do not meet.
port=$((20000 + $$ % 20000))
host=$(hostname -s)
cat > "$work/slurm.conf" << CONF
ClusterName=collido_test
SlurmctldHost=$host
SlurmctldPort=$port
SlurmdPort=$((port + 1))
AuthType=auth/munge
AuthInfo=socket=$socket
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/log/slurmctld.log
SlurmdLogFile=$work/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
ReturnToService=2
NodeName=$host CPUs=$(nproc) State=UNKNOWN
PartitionName=local Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$work/slurm.conf
slurmctld -c -f "$SLURM_CONF" || skip_with_log "slurmctld could not start" "$work/log/slurmctld.log"
slurmd -f "$SLURM_CONF" || skip_with_log "slurmd could not start" "$work/log/slurmd.log"
for _ in $(seq 60); do
  if sinfo --noheader --states=idle --format=%n 2> /dev/null | grep -q .; then break; fi
  sleep 0.5
done
sinfo --noheader --states=idle --format=%n | grep -q . ||
  skip_with_log "the node did not come up idle in 30 s" "$work/log/slurmd.log"

# A small study: two scenes, two settings of the OBB tree, four combinations in two shards.
cd "$source_dir"
study=(scenes/interlocked_tori.json scenes/stacked_plates.json
       --backends 'obbtree,obbtree[float_boxes=true]' --repetitions 1)
"$source_dir/tools/slurm_study.sh" --shards 2 --out "$work/cluster" --collido "$collido" --wait \
  -- "${study[@]}"
"$collido" study "${study[@]}" --out "$work/whole" --quiet > /dev/null

for folder in "$work/cluster/shard-0" "$work/cluster/shard-1" "$work/cluster/all"; do
  [[ -f $folder/table.txt ]] || { echo "missing $folder/table.txt" >&2; exit 1; }
done
[[ -f $work/cluster/all/report.html ]] || { echo "the merge job wrote no report" >&2; exit 1; }
# Both shards read or wrote the one store.
[[ -n $(ls "$work/cluster/oracle") ]] || { echo "the shared oracle store is empty" >&2; exit 1; }

python3 - "$work/whole" "$work/cluster/all" << 'PY'
import json, os, sys
def answers(folder):
    times = {"median_us", "floor_us", "update_us"}
    rows = []
    for line in open(os.path.join(folder, "records.jsonl")):
        record = json.loads(line)
        rows.append(json.dumps({k: v for k, v in record.items() if k not in times}, sort_keys=True))
    return sorted(rows)
whole, merged = sys.argv[1], sys.argv[2]
ids = [sorted(os.listdir(os.path.join(f, "results"))) for f in (whole, merged)]
if ids[0] != ids[1]:
    sys.exit(f"combinations differ: unsharded {ids[0]}, merged {ids[1]}")
a, b = answers(whole), answers(merged)
if a != b:
    sys.exit(f"answers differ ({len(a)} records unsharded, {len(b)} merged)")
print(f"merged study equals the unsharded one: {len(ids[0])} combinations, {len(a)} records")
PY
