#!/usr/bin/env bash
# Writes the image textures of the reference scenes (reference/textures/),
# committed; rerun only to change them. Needs oiiotool (openimageio-tools).
#
# noise16_37x23_rgba.png: 37 x 23 (odd, so that wrapping and texel centres
# do not line up with powers of two), 16-bit RGBA. RGB is uniform noise
# with a fixed seed, so the low 8 bits of every code matter (an 8-bit
# round trip anywhere moves a value by up to 128/65535); alpha is a 3 x 2
# texel checker of 0 and 1, so a reader that multiplies colour by alpha
# blackens half the texels. The colour is stored unassociated (as given).
set -euo pipefail
cd "$(dirname "$0")/.."
out=reference/textures
mkdir -p "$out"
oiiotool --nosoftwareattrib \
  --pattern noise:type=uniform:min=0:max=1:seed=13 37x23 3 \
  --pattern checker:width=3:height=2:color1=0:color2=1 37x23 1 \
  --chappend --chnames R,G,B,A --attrib oiio:UnassociatedAlpha 1 \
  -d uint16 -o "$out/noise16_37x23_rgba.png"
echo "wrote $out/noise16_37x23_rgba.png"
