#!/usr/bin/env bash
# The test command, from a fresh Debian 12 machine: install what is missing,
# build, and run the default test set (CTest label `unit`).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
cd build
ctest -L unit --output-on-failure -j"$(nproc)"
