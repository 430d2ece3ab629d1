#!/usr/bin/env bash
# `rpt sweep --slurm` on a real Slurm cluster: starts a one-node cluster on this machine (munged,
# slurmctld and slurmd on localhost, a generated slurm.conf, everything in one temporary folder, no
# systemd), submits a small sweep as a job array of shards plus the dependent merge job, waits for
# it, and checks that the merged table equals the same sweep run unsharded (every column but the
# timings, exactly). Stops its daemons and removes the folder on exit, also on failure or Ctrl-C.
#
#   bash scripts/ci_slurm.sh            (after building rpt: BUILD_DIR, default build)
#
# Where Slurm is not installed (bash scripts/install_deps.sh --tests installs Debian's slurm-wlm
# and munge) or cannot start here, it prints "SKIP: ..." and exits 0; RPT_SLURM_REQUIRED=1 makes
# that a failure. Exit 1 when the sweep on the cluster fails or differs.
set -euo pipefail
cd "$(dirname "$0")/.."
RPT="$(pwd)/${BUILD_DIR:-build}/rpt"
WAIT_S="${RPT_SLURM_TIMEOUT:-90}"   # for the cluster to come up, and again for the jobs
PATH="$PATH:/usr/sbin:/sbin"         # munged, slurmctld and slurmd live in /usr/sbin
NODE=rpt-ci-node

skip() {
  echo "SKIP: Slurm cluster test: $*"
  if [ "${RPT_SLURM_REQUIRED:-0}" = 1 ]; then exit 1; fi
  exit 0
}

for tool in munged munge slurmctld slurmd sbatch squeue sinfo scancel python3; do
  command -v "$tool" >/dev/null || skip "'$tool' not found (bash scripts/install_deps.sh --tests installs slurm-wlm and munge)"
done
if [ ! -x "$RPT" ]; then
  echo "error: $RPT not found: build rpt first" >&2
  exit 1
fi

# munged refuses a socket folder that others cannot traverse: the folder is 755, the key 400.
tmp=$(mktemp -d "${TMPDIR:-/tmp}/rpt-slurm.XXXXXX")
chmod 755 "$tmp"
daemons=()  # process ids, in start order
cluster_up=0

cleanup() {
  local status=$?
  trap - EXIT INT TERM
  if [ "$cluster_up" = 1 ]; then scancel --quiet --full "--user=$(id -un)" 2>/dev/null || true; fi
  local i
  for ((i = ${#daemons[@]} - 1; i >= 0; i--)); do kill "${daemons[i]}" 2>/dev/null || true; done
  # Up to 10 s for them to stop, then SIGKILL.
  for _ in $(seq 1 50); do
    local alive=0
    for pid in "${daemons[@]}"; do kill -0 "$pid" 2>/dev/null && alive=1; done
    [ "$alive" = 0 ] && break
    sleep 0.2
  done
  for pid in "${daemons[@]}"; do kill -9 "$pid" 2>/dev/null || true; done
  if [ "$status" != 0 ] && [ "${RPT_SLURM_KEEP:-0}" != 1 ]; then
    for log in "$tmp"/*.log "$tmp"/cluster/slurm/*.log; do
      [ -f "$log" ] && { echo "--- $log (last lines)"; tail -n 15 "$log"; }
    done
  fi
  if [ "${RPT_SLURM_KEEP:-0}" = 1 ]; then echo "kept $tmp"; else rm -rf "$tmp"; fi
  exit "$status"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

# Two free TCP ports on localhost for slurmctld and slurmd (so several runs can share a machine).
read -r ctld_port slurmd_port < <(python3 -c '
import socket
s = [socket.socket() for _ in range(2)]
for x in s: x.bind(("127.0.0.1", 0))
print(*[x.getsockname()[1] for x in s])')

mkdir -p "$tmp/munge" "$tmp/state" "$tmp/spool"
chmod 755 "$tmp/munge"
head -c 1024 /dev/urandom >"$tmp/munge/munge.key"
chmod 400 "$tmp/munge/munge.key"
user=$(id -un)
cat >"$tmp/slurm.conf" <<EOF
# A one-node cluster on localhost for scripts/ci_slurm.sh; every path in $tmp.
ClusterName=rptci
SlurmctldHost=$(hostname -s)(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$tmp/munge/munge.socket
SlurmUser=$user
SlurmdUser=$user
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/slurmctld.log
SlurmdLogFile=$tmp/slurmd.log
MailProg=/bin/true
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
NodeName=$NODE NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=ci Nodes=$NODE Default=YES MaxTime=10 State=UP
EOF
export SLURM_CONF="$tmp/slurm.conf"

munged --foreground --key-file="$tmp/munge/munge.key" --socket="$tmp/munge/munge.socket" \
  --pid-file="$tmp/munge/munged.pid" --log-file="$tmp/munged.log" --seed-file="$tmp/munge/munged.seed" \
  >"$tmp/munged.out" 2>&1 &
daemons+=($!)
for _ in $(seq 1 50); do [ -S "$tmp/munge/munge.socket" ] && break; sleep 0.1; done
if ! munge --socket="$tmp/munge/munge.socket" -n 2>/dev/null | unmunge --socket="$tmp/munge/munge.socket" >/dev/null 2>&1; then
  tail -n 5 "$tmp/munged.log" "$tmp/munged.out" 2>/dev/null || true
  skip "munged did not start (its log is above)"
fi
slurmctld -D -f "$tmp/slurm.conf" >"$tmp/slurmctld.out" 2>&1 &
daemons+=($!)
cluster_up=1
slurmd -D -f "$tmp/slurm.conf" -N "$NODE" >"$tmp/slurmd.out" 2>&1 &
daemons+=($!)
state=""
for _ in $(seq 1 $((WAIT_S * 5))); do
  state=$(sinfo --noheader --nodes="$NODE" --format=%T 2>/dev/null || true)
  [ "$state" = idle ] && break
  for pid in "${daemons[@]}"; do kill -0 "$pid" 2>/dev/null || state=died; done
  [ "$state" = died ] && break
  sleep 0.2
done
if [ "$state" != idle ]; then
  tail -n 5 "$tmp/slurmctld.log" "$tmp/slurmd.log" "$tmp/slurmctld.out" "$tmp/slurmd.out" 2>/dev/null || true
  skip "the one-node cluster did not come up (node state '${state:-none}'; the daemons' logs are above)"
fi
echo "one-node Slurm cluster up: $(sinfo --version), node $NODE with $(nproc) CPUs"

# The sweep: 6 configurations of a short synthetic suite, unsharded here and as 3 shards on Slurm.
sweep=(sweep --dataset synthetic --param frames=20 --grid merge.top_k=0,3,5 --grid prefilter.enabled=true,false)
"$RPT" "${sweep[@]}" --threads 1 --out "$tmp/whole" >"$tmp/whole.log"
start=$(date +%s)
"$RPT" "${sweep[@]}" --out "$tmp/cluster" --slurm 3 --slurm-option time=5 | tee "$tmp/submit.log"
for _ in $(seq 1 $((WAIT_S * 5))); do
  [ -z "$(squeue --noheader 2>/dev/null)" ] && break
  sleep 0.2
done
if [ -n "$(squeue --noheader 2>/dev/null)" ]; then
  squeue
  echo "error: the jobs did not finish within ${WAIT_S} s" >&2
  exit 1
fi
echo "jobs finished after $(($(date +%s) - start)) s"
if [ ! -f "$tmp/cluster/sweep.json" ]; then
  echo "error: the merge job wrote no $tmp/cluster/sweep.json" >&2
  exit 1
fi
cat "$tmp/cluster/slurm/merge.log"

# Rows equal but for the timings (and the run's own description: machine, command, threads).
python3 - "$tmp/whole/sweep.json" "$tmp/cluster/sweep.json" <<'EOF'
import json, re, sys
whole, cluster = (json.load(open(p)) for p in sys.argv[1:3])
timing = re.compile(r"time|fps|per_s")
def table(sweep):
    return [{**{k: v for k, v in row.items() if k != "summary"},
             "summary": {k: v for k, v in row["summary"].items() if not timing.search(k)}} for row in sweep["rows"]]
a, b = table(whole), table(cluster)
if a != b or whole["total"] != cluster["total"] or whole["base"] != cluster["base"]:
    for x, y in zip(a, b):
        if x != y: print("unsharded:", x, "\ncluster:  ", y, file=sys.stderr)
    sys.exit("error: the merged sweep from the cluster differs from the unsharded sweep")
columns = sorted(a[0]["summary"]) if a else []
print(f"OK: {len(a)} configurations merged from the cluster equal the unsharded sweep "
      f"in all {len(columns)} non-timing columns ({', '.join(columns)})")
EOF
