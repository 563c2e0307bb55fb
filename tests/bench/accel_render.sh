#!/usr/bin/env bash
# The whole path-traced render of the Cornell box with the bunny, timed per
# accelerator against Embree in one run: `lightlab --threads T render
# cornell_bunny_{59k,235k}.json -t path -a A --width 128 --height 128 --spp 64`,
# render seconds (time_seconds.render: shading included, the structure's build
# not), best of three rounds, the accelerators interleaved within a round so a
# change in the machine's load hits them all alike.
#   tests/bench/accel_render.sh [BUILD_DIR] [ACCELERATORS...]   (defaults: build; bvh bvh4 kdtree bsp octree embree)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
shift || true
accels=("$@")
[ ${#accels[@]} -gt 0 ] || accels=(bvh bvh4 kdtree bsp octree embree)
out=$(mktemp -d /tmp/accel_render.XXXX)
for scene in 59k 235k; do
  for threads in 1 2; do
    for round in 1 2 3; do
      for a in "${accels[@]}"; do
        "$build/lightlab" --quiet --threads "$threads" render "$build/data/scenes/cornell_bunny_$scene.json" -t path \
          -a "$a" --width 128 --height 128 --spp 64 -o "$out/$a.pfm" --stats "$out/$scene-$threads-$round-$a.json" >/dev/null
      done
    done
  done
done
python3 - "$out" "${accels[@]}" <<'EOF'
import json, sys
out, accels = sys.argv[1], sys.argv[2:]
print("| bunny | threads | " + " | ".join(accels) + " |")
print("|---" * (len(accels) + 2) + "|")
for scene in ("59k", "235k"):
    for threads in (1, 2):
        best = {a: min(json.load(open(f"{out}/{scene}-{threads}-{r}-{a}.json"))["time_seconds"]["render"]
                       for r in (1, 2, 3)) for a in accels}
        ref = best.get("embree")
        cells = [f"{best[a]:.2f} s" + (f" ({ref / best[a]:.2f}x)" if ref and a != "embree" else "") for a in accels]
        print(f"| {scene} | {threads} | " + " | ".join(cells) + " |")
EOF
