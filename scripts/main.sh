#!/usr/bin/env bash
# The main job, from a fresh Debian 12 machine: install what is missing,
# build, and render the default reference scene set (reference/scenes/)
# with the reference renderer into results/renders/ (EXR + 16-bit PNG per
# scene, and timings.tsv).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
bash scripts/render-reference.sh
