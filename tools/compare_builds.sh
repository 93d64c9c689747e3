#!/usr/bin/env bash
# Renders every shipped scene by every method with two facet executables and checks that the frames
# are bit-identical (`facet compare` max_abs 0): for changes that must not move a pixel, such as the
# direct pass's program variants (docs/render_speed.md, "Pipeline set-up").
#   tools/compare_builds.sh OLD_FACET NEW_FACET OUT_DIR [WIDTH HEIGHT]
# Prints one line per render and exits 1 if any differs or fails.
set -u
if [ $# -lt 3 ]; then
  echo "usage: $0 OLD_FACET NEW_FACET OUT_DIR [WIDTH HEIGHT]" >&2
  exit 2
fi
old=$1 new=$2 out=$3 width=${4:-64} height=${5:-36}
scenes_dir=$(cd "$(dirname "$0")/../scenes" && pwd)
mkdir -p "$out"
failures=0 runs=0
check() {  # scene, label, render arguments...
  local scene=$1 label=$2
  shift 2
  local stem
  stem=$(basename "${scene%.*}")_$label
  runs=$((runs + 1))
  if ! "$old" render "$scene" -o "$out/$stem.old.exr" --width "$width" --height "$height" --no-preview "$@" \
      >/dev/null 2>"$out/$stem.old.err" ||
     ! "$new" render "$scene" -o "$out/$stem.new.exr" --width "$width" --height "$height" --no-preview "$@" \
      >/dev/null 2>"$out/$stem.new.err"; then
    echo "FAILED  $stem: $(tail -n 1 "$out/$stem.old.err" "$out/$stem.new.err" | tr '\n' ' ')"
    failures=$((failures + 1))
    return
  fi
  local max_abs
  max_abs=$("$new" compare "$out/$stem.new.exr" "$out/$stem.old.exr" --json |
            sed -n 's/.*"max_abs": *\([^,}]*\).*/\1/p')
  if [ "$max_abs" = "0" ] || [ "$max_abs" = "0.0" ]; then
    echo "same    $stem"
  else
    echo "DIFFERS $stem max_abs $max_abs"
    failures=$((failures + 1))
  fi
}
for scene in "$scenes_dir"/*.json "$scenes_dir"/*.gltf; do
  for method in naive mip colormip filtered filtered:ss:2 ss:2 filtered:table; do
    check "$scene" "${method//:/-}" --method "$method"
  done
  check "$scene" aovs --method filtered --aov depth,normal,uv,error
  if grep -q '"diffraction"' "$scene"; then
    for diffraction in spectral preintegrated orders; do
      check "$scene" "$diffraction" --diffraction "$diffraction"
    done
  fi
done
echo "$((runs - failures)) of $runs renders bit-identical"
[ "$failures" -eq 0 ]
