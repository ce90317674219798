#!/usr/bin/env bash
# A single-node Slurm cluster on localhost (munge, slurmctld, slurmd from Debian's packages),
# for trying the job-array scripts beside it without a cluster. Needs root (slurmd starts the
# jobs as their owner); every file it writes is under DIR, and `down` stops what `up` started.
#
# Usage: local-cluster.sh up DIR     start; prints the line to export (SLURM_CONF=DIR/slurm.conf)
#        local-cluster.sh down DIR   stop the daemons started by `up DIR`
# Install: apt-get install slurmctld slurmd slurm-client munge
set -euo pipefail
cmd="${1:?usage: local-cluster.sh up|down DIR}"
dir="$(mkdir -p "${2:?usage: local-cluster.sh up|down DIR}" && cd "$2" && pwd)"

stop_pidfile() { # FILE: stop the process whose pid FILE holds, if it runs
  [ -f "$1" ] || return 0
  local pid
  pid=$(cat "$1")
  kill "$pid" 2>/dev/null || true
  for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
  rm -f "$1"
}

if [ "$cmd" = down ]; then
  stop_pidfile "$dir/slurmd.pid"
  stop_pidfile "$dir/slurmctld.pid"
  stop_pidfile "$dir/munge/munged.pid"
  exit 0
fi
[ "$cmd" = up ] || { echo "local-cluster.sh: unknown command '$cmd' (up or down)" >&2; exit 2; }

for tool in munged slurmctld slurmd sbatch scontrol; do
  command -v "$tool" >/dev/null || PATH="$PATH:/usr/sbin"
  command -v "$tool" >/dev/null || {
    echo "local-cluster.sh: '$tool' is missing; install: apt-get install slurmctld slurmd slurm-client munge" >&2
    exit 2
  }
done
[ "$(id -u)" = 0 ] || { echo "local-cluster.sh: run as root (slurmd starts jobs as their owner)" >&2; exit 2; }

node="$(hostname -s)"
cpus="$(nproc)"
mem_mb=$(( $(awk '/MemTotal/ {print $2}' /proc/meminfo) / 1024 - 512 ))
mkdir -p "$dir/state" "$dir/spool" "$dir/munge"
chown munge:munge "$dir/munge"
# munged runs as the munge user: every folder above its own must let it pass (mktemp -d
# makes mode 700 folders, which do not).
runuser -u munge -- test -w "$dir/munge" || {
  echo "local-cluster.sh: the munge user cannot reach $dir/munge: every folder above it needs" \
    "o+x (mktemp -d makes mode 700 folders); chmod o+x them or choose DIR elsewhere" >&2
  exit 2
}
# Ports away from Slurm's defaults, so a real installation on the same host is left alone.
cat > "$dir/slurm.conf" <<CONF
ClusterName=gartowen-local
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=${GARTOWEN_SLURMCTLD_PORT:-16817}
SlurmdPort=${GARTOWEN_SLURMD_PORT:-16818}
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$dir/munge/munge.socket
CredType=cred/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SwitchType=switch/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
ReturnToService=2
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$mem_mb State=UNKNOWN
PartitionName=local Nodes=$node Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$dir/slurm.conf"

runuser -u munge -- munged --socket="$dir/munge/munge.socket" --pid-file="$dir/munge/munged.pid" \
  --log-file="$dir/munge/munged.log" --seed-file="$dir/munge/munged.seed"
slurmctld -f "$SLURM_CONF"
slurmd -f "$SLURM_CONF"

# Ready when the node accepts jobs (idle); a daemon that died is reported with its log.
for _ in $(seq 150); do
  state="$(sinfo -h -N -o %t 2>/dev/null | head -1 || true)"
  case "$state" in idle*|mix*|alloc*) echo "export SLURM_CONF=$SLURM_CONF"; exit 0 ;; esac
  sleep 0.2
done
echo "local-cluster.sh: the node did not come up (state '${state:-none}'); logs:" >&2
tail -n 20 "$dir/slurmctld.log" "$dir/slurmd.log" "$dir/munge/munged.log" >&2 || true
"$0" down "$dir"
exit 1
