#!/usr/bin/env bash
# The test command, from a fresh Debian 12 machine: install what is missing,
# build, and run the default test set: CTest labels `unit`, `cross`
# (the cross-renderer tests need POV-Ray and Blender, which the install
# step provides; a missing renderer fails them) and `golden` (the reference
# renderer against the committed golden images, neither tool needed).
#
# Then the robustness checks (docs/robustness.md): the unit tests again,
# built with clang under AddressSanitizer and UndefinedBehaviorSanitizer
# in build-asan/, and a short fixed-seed run of each fuzz target (label
# `fuzz`). Both parts always run; the exit status is non-zero if either
# failed.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
status=0
(cd build && ctest -L "unit|cross|golden" --output-on-failure -j"$(nproc)") || status=1

cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DXVAL_SANITIZE=ON -DXVAL_FUZZ=ON
cmake --build build-asan -j"$(nproc)" --target xval_unit_tests xval xval_blender_graph_samples \
  xval_model_probe xval_model_corpus \
  xval_fuzz_scene xval_fuzz_spec xval_fuzz_plan xval_fuzz_record xval_fuzz_tolerances xval_fuzz_model \
  xval_fuzz_results xval_fuzz_golden xval_fuzz_renderer_file xval_fuzz_pack_manifest
(cd build-asan && ctest -L "unit|fuzz" --output-on-failure -j"$(nproc)") || status=1
exit $status
