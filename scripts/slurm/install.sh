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

bash "$(dirname "$0")/../apt-install-missing.sh" slurm/install "${packages[@]}"
