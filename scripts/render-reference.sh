#!/usr/bin/env bash
# Renders every scene of reference/scenes/ with the reference renderer.
# Usage: scripts/render-reference.sh [OUT_DIR]   (default results/renders)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-results/renders}
xval=build/renderer/xval
[ -x "$xval" ] || { echo "render-reference: $xval not built (run scripts/build.sh)" >&2; exit 2; }
mkdir -p "$out"
scenes=(reference/scenes/*.json)
n=${#scenes[@]}
stats="$out/stats"
rm -rf "$stats"
mkdir -p "$stats"
SECONDS=0
i=0
for scene in "${scenes[@]}"; do
  i=$((i + 1))
  name=$(basename "$scene" .json)
  printf '[%2d/%d] %-28s ' "$i" "$n" "$name"
  log=$("$xval" render "$scene" -o "$out/$name.exr" --stats "$stats/$name.json" 2>&1) ||
    { echo "FAILED"; echo "$log" >&2; exit 1; }
  "$xval" render "$scene" -o "$out/$name.png" -q
  summary=$(echo "$log" | tail -n 1)
  echo "${summary#xval render: wrote }"
done
# timings.tsv from the renders' --stats files (JSON), one row per scene.
python3 - "$stats" "$out/timings.tsv" <<'PY'
import json, pathlib, sys
stats, out = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
cols = ["scene", "width", "height", "spp", "precision", "visibility", "culled_triangles", "shading",
        "setup_s", "frame_s"]
rows = ["\t".join(cols)]
for f in sorted(stats.glob("*.json")):
    s = json.loads(f.read_text())
    rows.append("\t".join(str(s[c]).replace("\t", " ").replace("\n", " ") for c in cols))
tmp = out.with_suffix(".tsv.partial")
tmp.write_text("\n".join(rows) + "\n")
tmp.replace(out)
PY
echo "rendered $n scenes into $out in ${SECONDS} s (EXR and PNG each; timings.tsv)"
