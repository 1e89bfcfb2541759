#!/bin/sh
# A stand-in for a user's renderer (docs/renderer-file.md), driven by
# tests/cli/renderer_file.cmake: MODE SCENE OUTPUT WIDTH HEIGHT.
# Each mode is one way a renderer can go wrong, and `pass` one way it can
# go right (it hands the scene to the reference renderer: XVAL names it).
#   --version        prints "standin 1.0"
#   pass             the reference renderer's image of SCENE
#   dim              that image at half its value (a renderer that disagrees)
#   dim5             that image 5% darker (a small fault: an exposure slip)
#   fail             complains and exits 3
#   hang             never finishes (the time-out must stop it)
#   no-image         exits 0 without writing OUTPUT
#   wrong-size       a (WIDTH+1) x HEIGHT image
#   two-channels     a 2-channel image
#   nan              an RGBA image whose red channel is NaN
#   bad-bytes        prints bytes that are no UTF-8 (0xFF 0xFE) after 3000
#                    euro signs (3 bytes each), so that the log's quoted
#                    4 KiB tail starts inside one, and exits 3
set -eu
if [ "${1:-}" = "--version" ]; then echo "standin 1.0"; exit 0; fi
mode=$1 scene=$2 output=$3 width=$4 height=$5
echo "standin: mode $mode, scene $scene"
case "$mode" in
  pass) exec "$XVAL" render "$scene" -o "$output" -q ;;
  dim) "$XVAL" render "$scene" -o "$output.full.exr" -q
       exec oiiotool "$output.full.exr" --mulc 0.5,0.5,0.5,1 -o "$output" ;;
  dim5) "$XVAL" render "$scene" -o "$output.full.exr" -q
        exec oiiotool "$output.full.exr" --mulc 0.95,0.95,0.95,1 -o "$output" ;;
  fail) echo "standin: the engine crashed (simulated)"; exit 3 ;;
  hang) exec sleep 600 ;;
  no-image) exit 0 ;;
  wrong-size) exec oiiotool --create "$((width + 1))x$height" 4 -d float -o "$output" ;;
  two-channels) exec oiiotool --create "${width}x$height" 2 -d float -o "$output" ;;
  nan) exec oiiotool --pattern constant:color=nan,0,0,1 "${width}x$height" 4 -d float -o "$output" ;;
  bad-bytes) i=0; while [ $i -lt 3000 ]; do printf '\342\202\254'; i=$((i + 1)); done
             printf '\n\377\376 end\n'; exit 3 ;;
  *) echo "standin: unknown mode $mode"; exit 2 ;;
esac
