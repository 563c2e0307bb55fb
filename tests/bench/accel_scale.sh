#!/usr/bin/env bash
# The scale study of issue 29: the 15-million-triangle bunny (six Loop
# subdivisions of data/meshes/bunny.ply, made on demand) built and path traced
# with each accelerator, one after the other in one run: build seconds, the
# structure's bytes per triangle (AcceleratorStats::memoryBytes; Embree's from
# its memory monitor), the process's peak memory, and the render.
#   tests/bench/accel_scale.sh [BUILD_DIR] [ACCELERATORS...]   (defaults: build; bvh bvh4 kdtree embree)
# Long (minutes) and memory-hungry (several GB): a measurement, never a CI test.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
shift || true
accels=("$@")
[ ${#accels[@]} -gt 0 ] || accels=(bvh bvh4 kdtree embree)
ninja -C "$build" lightlab lightlab_bunny_15m >/dev/null
scene=$build/data/scenes/bunny_15m.json
out=$(mktemp -d /tmp/accel_scale.XXXX)
echo "scene: $scene; $(nproc) threads; output in $out"
printf '%-8s %10s %12s %10s %12s %12s %12s\n' accel build_s MB bytes/tri peak_RSS_MB render_s Mrays/s
for a in "${accels[@]}"; do
  /usr/bin/time -f '%M' -o "$out/$a.rss" "$build/lightlab" render "$scene" -t path -a "$a" --width 256 --height 256 \
    --spp 4 -o "$out/$a.png" --stats "$out/$a.json" >/dev/null 2>"$out/$a.log" || { echo "$a: failed (see $out/$a.log)"; continue; }
  python3 - "$out/$a.json" "$out/$a.rss" "$a" <<'EOF'
import json, sys
j = json.load(open(sys.argv[1])); s = j["accelerator_stats"]
tris = 3674 * 4**6 + 2  # bunny.ply's triangles times 4^6, and the floor quad's two
rss = int(open(sys.argv[2]).read().split()[-1]) / 1024
t = j["time_seconds"]
print("%-8s %10.2f %12.1f %10.1f %12.0f %12.2f %12.2f" % (sys.argv[3], s["build_seconds"], s["memory_bytes"] / 1e6,
      s["memory_bytes"] / tris, rss, t["render"], j["mrays_per_second"]))
EOF
done
