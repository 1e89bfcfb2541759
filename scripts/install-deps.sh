#!/usr/bin/env bash
# Installs, from Debian 12 packages, everything the project builds and runs
# with. Only packages that are missing are installed; `apt-get update` runs
# first whenever something is missing (package lists may be stale or empty).
set -euo pipefail

packages=(
  # build
  build-essential cmake pkg-config
  # the sanitizer build and the fuzz targets (docs/robustness.md)
  clang libclang-rt-14-dev
  # libraries
  libopenimageio-dev openimageio-tools libopenexr-dev libpng-dev libglm-dev nlohmann-json3-dev libcli11-dev
  libfmt-dev libtinygltf-dev libassimp-dev libembree-dev libhwy-dev libgtest-dev libgmock-dev libbenchmark-dev
  # the report's template (renderer/validate/report/report_page.mustache)
  libkainjow-mustache-dev
  # the gl renderer: OpenGL 4.5 core through EGL (Mesa llvmpipe without a GPU)
  libopengl-dev libegl-dev libegl-mesa0 libgl1-mesa-dri
  liblcms2-dev libssl-dev
  # xval pack's .tar.gz archives
  libarchive-dev
  # the shader renderer: HLSL -> SPIR-V -> GLSL 4.50 (docs/shaders.md)
  glslang-tools spirv-cross
  # Assimp's test corpus: the model loader's robustness test (tests/corpus)
  assimp-testmodels
  # external renderers and what Blender's glTF add-on needs
  povray blender python3-numpy
  # the report: plots, and the headless browser its test opens it in
  gnuplot-nox chromium
  # JUnit XML checked against its schema (tests/junit/junit.xsd)
  libxml2-utils
  # the mutation test's wrong renderers and its measure (tests/mutation, docs/mutation-test.md)
  python3-openimageio
)
# Node.js for the Khronos glTF Validator (tests): Debian's, unless a node
# is already installed.
command -v node >/dev/null 2>&1 && command -v npm >/dev/null 2>&1 || packages+=(nodejs npm)

bash "$(dirname "$0")/apt-install-missing.sh" install-deps "${packages[@]}"

# The glTF validator, from the npm registry, pinned by tests/tools/package-lock.json.
here=$(cd "$(dirname "$0")/.." && pwd)
if [ ! -d "$here/tests/tools/node_modules/gltf-validator" ]; then
  echo "install-deps: npm ci in tests/tools"
  (cd "$here/tests/tools" && npm ci --no-audit --no-fund)
fi
