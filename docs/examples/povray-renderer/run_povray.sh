#!/bin/sh
# POV-Ray 3.7 as a renderer defined by a file (docs/renderer-file.md):
# run_povray.sh EXPORT_FOLDER OUTPUT SPP. xval's POV-Ray export
# (input "pov") holds scene.pov and scene.ini; scene.ini renders a 16-bit
# linear PNG with alpha, scene.png. At 1 sample per pixel that is the
# image xval asks for; at more, scene.ini renders n W x n H for n x n
# samples and this wrapper would have to box-filter it, so it refuses.
set -eu
export_folder=$1 output=$2 spp=$3
if [ "$spp" != 1 ]; then
  echo "run_povray.sh: $spp samples per pixel: only 1 is supported by this example" >&2
  exit 2
fi
cd "$export_folder"
povray scene.ini
# xval reads the image by its content: a PNG under OUTPUT's name is fine.
cp scene.png "$output"
