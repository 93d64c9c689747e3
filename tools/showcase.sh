#!/usr/bin/env bash
# The quick start's pictures, from an already built facet:
#   OUT_DIR/default.exr (+ .png)   scenes/showcase.json with --method filtered, at the scene's 1280x720;
#   OUT_DIR/default_compare.png    naive, filtered and the CPU reference of a smaller frame, side by side,
#                                  each labelled with its time and its error against the reference.
# Usage: tools/showcase.sh FACET OUT_DIR [PICTURE_WIDTH COMPARE_WIDTH REFERENCE_GRID]
# (the defaults are the quick start's; tests/cli/showcase_test.cpp runs it small).
set -euo pipefail
facet=$1
out=$2
picture_width=${3:-1280}
compare_width=${4:-320}
grid=${5:-16}
scene="$(dirname "$0")/../scenes/showcase.json"
frames="$out/default_compare"

"$facet" render "$scene" -o "$out/default.exr" --method filtered --width "$picture_width"
for method in naive filtered; do
  "$facet" render "$scene" -o "$frames/$method.exr" --method "$method" --width "$compare_width" --no-preview
done
"$facet" reference "$scene" -o "$frames/reference.exr" --width "$compare_width" --grid "$grid"
"$facet" compare "$frames/naive.exr" "$frames/filtered.exr" "$frames/reference.exr" --sheet "$out/default_compare.png"
echo "facet: picture: $out/default.png (scene-linear: $out/default.exr)"
echo "facet: comparison: $out/default_compare.png (frames in $frames/)"
