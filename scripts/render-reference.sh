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
tsv="$out/timings.tsv.partial"
printf 'scene\twidth\theight\tspp\tprecision\tsetup_s\ttrace_s\n' > "$tsv"
SECONDS=0
i=0
for scene in "${scenes[@]}"; do
  i=$((i + 1))
  name=$(basename "$scene" .json)
  printf '[%2d/%d] %-28s ' "$i" "$n" "$name"
  log=$("$xval" render "$scene" -o "$out/$name.exr" 2>&1) || { echo "FAILED"; echo "$log" >&2; exit 1; }
  "$xval" render "$scene" -o "$out/$name.png" -q
  # "xval render: wrote F (WxH, N spp, P): setup S s, trace T s"
  summary=$(echo "$log" | tail -n 1)
  echo "${summary#xval render: wrote }"
  echo "$summary" | sed -E 's/.*\(([0-9]+)x([0-9]+), ([0-9]+) spp, ([a-z]+)\): setup ([0-9.]+) s, trace ([0-9.]+) s/\1\t\2\t\3\t\4\t\5\t\6/' \
    | sed "s/^/$name\t/" >> "$tsv"
done
mv "$tsv" "$out/timings.tsv"
echo "rendered $n scenes into $out in ${SECONDS} s (EXR and PNG each)"
