#!/usr/bin/env bash
# The test command, from a fresh Debian 12 machine: install what is missing,
# build, and run the default test set: CTest labels `unit` and `cross`
# (the cross-renderer tests need POV-Ray and Blender, which the install
# step provides; a missing renderer fails them).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
cd build
ctest -L "unit|cross" --output-on-failure -j"$(nproc)"
