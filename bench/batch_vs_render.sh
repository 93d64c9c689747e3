#!/usr/bin/env bash
# The closing note of issue #9: frames per second over the 60-frame camera path of
# scenes/noise_plane_flyover.json at 1280x720 with `filtered`, rendered by one `facet batch` (one
# Vulkan device, one pipeline, the moment MIP chain built once) against 60 separate
# `facet render --frame F` calls (each loads the scene, builds the texture and its MIP chain,
# creates the device and pipeline). Timed with hyperfine; previews off in both.
#   usage: bench/batch_vs_render.sh [FACET] [RUNS]
set -euo pipefail
cd "$(dirname "$0")/.."
facet=$(realpath "${1:-build/renderer/cli/facet}")
runs=${2:-3}
scene=$(realpath scenes/noise_plane_flyover.json)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/job.json" <<JOB
{"scenes": ["$scene"], "methods": ["filtered"], "output": "batch/{frame:04}.exr", "preview": false,
 "width": 1280, "height": 720}
JOB
cat > "$work/separate.sh" <<SEP
for f in \$(seq 0 59); do
  "$facet" render "$scene" --frame \$f --method filtered --width 1280 --height 720 --no-preview -o "$work/separate/\$f.exr" 2>/dev/null
done
SEP
hyperfine --runs "$runs" --export-json "$work/times.json" \
  --prepare "rm -rf '$work/batch' '$work/job.manifest.json'" --command-name "facet batch (60 frames)" \
  "'$facet' batch '$work/job.json' 2>/dev/null" \
  --prepare "rm -rf '$work/separate'" --command-name "60 x facet render --frame F" "bash '$work/separate.sh'"
python3 - "$work/times.json" <<'PY'
import json, sys
for r in json.load(open(sys.argv[1]))["results"]:
    print(f"{r['command']}: median {r['median']:.2f} s = {60 / r['median']:.2f} frames/s")
PY
