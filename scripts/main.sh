#!/usr/bin/env bash
# The main job, from a fresh Debian 12 machine: install what is missing,
# build, render the default reference scene set (reference/scenes/) with
# the reference renderer into results/renders/ (EXR + 16-bit PNG per scene,
# and timings.tsv), run the extremes matrix and the trade-off, then validate
# the set against every other renderer (POV-Ray, Blender, EEVEE, gl, and
# the paper's HLSL listing as printed, paper-listing, defined by
# reference/shaders/kotsarenko2012_table1.json: it compares on the scenes
# it expresses and is recorded as not expressible, with the reason, on
# the others; docs/shaders.md) into results/validation/ (results.json;
# exit 1 if a case is outside its tolerance, 2 on an error), with the
# Blender-import check of the model files as each mesh case's geometry
# check (validate's default renderers include blender-import;
# docs/model-files.md, "The Blender-import check").
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
bash scripts/render-reference.sh
build/renderer/xval extremes -o results/validation/extremes
build/renderer/xval tradeoff reference/scenes/table2_knot_yiq.json -o results/validation/tradeoff  # docs/tradeoff.md
# The report shows the two folders named here (recorded in results.json).
build/renderer/xval validate reference/scenes -o results/validation \
  --renderer-file reference/shaders/kotsarenko2012_table1.json \
  --extremes results/validation/extremes --tradeoff results/validation/tradeoff
