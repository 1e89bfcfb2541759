#!/usr/bin/env bash
# Stops the test cluster that start-local-cluster.sh started from
# STATE_DIR: cancels its jobs, then stops slurmd, slurmctld and munged by
# the process ids in their pid files (nothing else is signalled). Safe to
# run when nothing is running.
# Usage: scripts/slurm/stop-local-cluster.sh STATE_DIR
set -uo pipefail

[ $# -eq 1 ] || { echo "usage: $0 STATE_DIR" >&2; exit 2; }
[ -d "$1" ] || { echo "stop-local-cluster: $1: no such folder (nothing to stop)"; exit 0; }
state=$(cd "$1" && pwd)

# Jobs first, while the controller still runs.
if [ -f "$state/slurm.conf" ] && [ -f "$state/slurmctld.pid" ] &&
   kill -0 "$(cat "$state/slurmctld.pid")" 2>/dev/null; then
  SLURM_CONF="$state/slurm.conf" scancel --user="$(id -un)" 2>/dev/null || true
fi

stop() {  # NAME PIDFILE
  local name=$1 file=$2 pid
  [ -f "$file" ] || return 0
  pid=$(cat "$file")
  case "$pid" in ''|*[!0-9]*) rm -f "$file"; return 0 ;; esac
  if kill -0 "$pid" 2>/dev/null; then
    kill -TERM "$pid" 2>/dev/null
    for _ in $(seq 100); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    if kill -0 "$pid" 2>/dev/null; then
      echo "stop-local-cluster: $name ($pid) did not stop in 10 s; killing it" >&2
      kill -KILL "$pid" 2>/dev/null
    fi
  fi
  rm -f "$file"
  echo "stop-local-cluster: stopped $name ($pid)"
}
stop slurmd "$state/slurmd.pid"
stop slurmctld "$state/slurmctld.pid"
stop munged "$state/munge/munged.pid"
exit 0
