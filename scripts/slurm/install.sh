#!/usr/bin/env bash
# Installs, from Debian 12 packages, what the one-node test cluster needs
# (Slurm 22.05 controller, node daemon and client commands, and munge for
# authentication). Only missing packages are installed; `apt-get update`
# runs first whenever something is missing. Not part of
# scripts/install-deps.sh: only the `cluster` test needs Slurm.
# The packages' own services are not started here (start-local-cluster.sh
# starts private daemons with their own configuration).
set -euo pipefail

packages=(slurm-wlm slurmctld slurmd slurm-client munge)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done

SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
if [ ${#missing[@]} -eq 0 ]; then
  echo "slurm/install: all ${#packages[@]} packages present"
else
  echo "slurm/install: installing ${missing[*]}"
  $SUDO apt-get update
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y --no-install-recommends "${missing[@]}"
fi
