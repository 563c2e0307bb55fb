#!/usr/bin/env bash
# The GUI end to end under Xvfb (Mesa llvmpipe): open two-pane presets, take
# screenshots once every pane has finished, and check that each pane shows
# what a headless render of the same technique shows, that the wipe puts A
# left and B right of its split, and that the difference view is the heatmap
# of A against B; and that the cost view and the structure overlay appear.
#   gui_screenshot_test.sh LIGHTLAB CHECKER OUT_DIR
set -euo pipefail
LL=$1 CHECK=$2 OUT=$3
HERE=$(cd "$(dirname "$0")" && pwd)
ROOT=$(cd "$HERE/../.." && pwd)
rm -rf "$OUT" && mkdir -p "$OUT"
cd "$ROOT"

# Headless references: same scene, size, passes and seed as the presets.
common=(--quiet render data/scenes/cornell_box.json -t raycast -a none --width 160 --height 160 --spp 2)
"$LL" "${common[@]}" --set light_samples=16 -o "$OUT/a.pfm"
"$LL" "${common[@]}" --set light_samples=1 -o "$OUT/b.pfm"
# A wrong reference for the checker's own test: the box without its shadows (the rasterizer).
"$LL" --quiet render data/scenes/cornell_box.json -t blinn-phong --width 160 --height 160 --spp 2 -o "$OUT/no_shadows.pfm"

shot() {  # preset name -> OUT/name.png (+ .json)
  xvfb-run -a -n 160 -s '-noreset -screen 0 1280x800x24' "$LL" gui --preset "$HERE/$1.json" --screenshot "$OUT/$1.png" \
    --frames 3 --timeout 600 >/dev/null
}
shot two_panes
shot wipe
shot difference
shot structure
shot structure_bsp
shot cost
shot gpu_twin
shot cpu_gpu
shot ray_tree
shot light_paths

"$CHECK" "$OUT/two_panes.png" pane 0 "$OUT/a.pfm"
"$CHECK" "$OUT/two_panes.png" pane 1 "$OUT/b.pfm"
"$CHECK" "$OUT/wipe.png" pane 0 "$OUT/a.pfm" 0 0.3
"$CHECK" "$OUT/wipe.png" pane 1 "$OUT/b.pfm" 0.3 1
"$CHECK" "$OUT/difference.png" diff "$OUT/a.pfm" "$OUT/b.pfm"
"$CHECK" "$OUT/wipe.png" differs "$OUT/two_panes.png"
"$CHECK" "$OUT/difference.png" differs "$OUT/wipe.png"
# The cost view is the CLI's heatmap; the structure overlay drew the BVH's nodes.
"$LL" --quiet render data/scenes/bunny.json -a bvh --width 160 --height 160 --cost nodes -o "$OUT/cost_cli.png" >/dev/null
"$CHECK" "$OUT/cost.png" pane 0 "$OUT/cost_cli.png"
"$CHECK" "$OUT/structure.png" differs "$OUT/cost.png"
python3 -c "import json,sys; p=json.load(open('$OUT/structure.json'))['panes'][1]; sys.exit(0 if p['structure_nodes'] > 4 else 1)" \
  || { echo "FAIL: no structure overlay drawn"; exit 1; }
# The BSP tree's cells are polyhedra drawn by their edges: the overlay must change the picture under it.
"$LL" --quiet render data/scenes/cornell_bunny.json -t raycast -a bsp --set intersection=framework --width 160 \
  --height 160 -o "$OUT/bsp_cli.pfm" >/dev/null
python3 -c "import json,sys; p=json.load(open('$OUT/structure_bsp.json'))['panes'][0]; sys.exit(0 if p['structure_nodes'] > 8 else 1)" \
  || { echo "FAIL: no BSP cells drawn"; exit 1; }
if "$CHECK" "$OUT/structure_bsp.png" pane 0 "$OUT/bsp_cli.pfm" >/dev/null 2>&1; then
  echo "FAIL: the BSP cells left the picture unchanged"; exit 1
fi
"$CHECK" "$OUT/structure_bsp.png" legend 1  # the cells stop above the cost view's legend
echo "ok: cost view and structure overlay (BVH boxes, BSP cells)"
# The GPU twin shades like ray casting where nothing casts shadows (a lone lit sphere).
"$LL" --quiet render data/scenes/tests/sphere_point_light.json -t raycast -a bvh --set intersection=framework \
  --width 160 --height 160 -o "$OUT/sphere.pfm" >/dev/null
python3 -c "import json,sys; p=json.load(open('$OUT/gpu_twin.json'))['panes'][1]; sys.exit(0 if p['phase'] == 'done' and not p['error'] else 1)" \
  || { echo "FAIL: the GPU twin did not render"; exit 1; }
"$CHECK" "$OUT/gpu_twin.png" pane 1 "$OUT/sphere.pfm"
echo "ok: the GPU twin matches ray casting"
# Assignment 1 in the GUI: the software rasterizer's pane is the CLI's picture, and its GLSL twin agrees with it.
"$LL" --quiet render data/scenes/textured_floor.json -t blinn-phong --set samples=4 --width 160 --height 120 \
  -o "$OUT/floor_cpu.pfm" >/dev/null
"$CHECK" "$OUT/cpu_gpu.png" pane 0 "$OUT/floor_cpu.pfm"
"$CHECK" "$OUT/cpu_gpu.png" pane 1 "$OUT/floor_cpu.pfm"
echo "ok: blinn-phong and blinn-phong-gl agree"
# Assignment 3 in the GUI: whitted renders as on the command line, and the clicked pixel's ray tree is drawn.
"$LL" --quiet render data/scenes/whitted_1980.json -t whitted -a bvh --width 320 --height 240 -o "$OUT/whitted.pfm" >/dev/null
"$CHECK" "$OUT/ray_tree.png" pane 1 "$OUT/whitted.pfm"
python3 -c "import json,sys; t=json.load(open('$OUT/ray_tree.json'))['ray_tree']; sys.exit(0 if t['nodes'] > 10 and t['pane'] == 0 else 1)" \
  || { echo "FAIL: no ray tree for the inspected pixel"; exit 1; }
if "$CHECK" "$OUT/ray_tree.png" pane 0 "$OUT/whitted.pfm" >/dev/null; then  # the same picture plus the rays
  echo "FAIL: the ray tree is not drawn over pane A"; exit 1
fi
echo "ok: whitted pane and its ray tree"
# Radiosity's bounces in four panes (a bundled preset): every pane finishes, the patches are solved once.
xvfb-run -a -n 160 -s '-noreset -screen 0 1280x800x24' "$LL" gui --preset "$ROOT/data/presets/radiosity_bounces.json" \
  --screenshot "$OUT/radiosity.png" --frames 3 --timeout 600 >/dev/null
python3 -c "import json,sys; ps=json.load(open('$OUT/radiosity.json'))['panes'][:4]; \
sys.exit(0 if all(p['phase'] == 'done' and not p['error'] for p in ps) else 1)" \
  || { echo "FAIL: the radiosity panes did not finish"; exit 1; }
echo "ok: radiosity bounces"
# The light-path view: the CLI's mosaic (render --stats writes OUT.light-paths.pfm), a label per tile.
"$LL" --quiet render data/scenes/cornell_box.json -t path -a bvh --width 160 --height 160 --spp 8 \
  --stats "$OUT/paths.json" -o "$OUT/paths.pfm" >/dev/null
"$CHECK" "$OUT/light_paths.png" pane 0 "$OUT/paths.light-paths.pfm"
"$LL" --quiet render data/scenes/cornell_box.json -t radiosity --width 160 --height 160 --spp 4 \
  --set hemicube_res=16 --stats "$OUT/bounces.json" -o "$OUT/bounces.pfm" >/dev/null
"$CHECK" "$OUT/light_paths.png" pane 1 "$OUT/bounces.light-paths.pfm"
python3 - "$OUT/light_paths.json" <<'PY' || { echo "FAIL: light-path tiles"; exit 1; }
import json, sys
panes = json.load(open(sys.argv[1]))['panes']
for pane in panes[:2]:  # path's classes, then radiosity's bounces E, KE, K^2E+...
    tiles = pane['light_path_tiles']
    names = [t['name'] for t in tiles]
    assert names == ['picture', 'emission', 'direct', 'indirect'], (pane['technique'], names)
    shares = [t['share'] for t in tiles[1:]]
    assert abs(sum(shares) - 1) < 1e-4, shares
# The two decompositions agree within a few points.
a, b = ([t['share'] for t in p['light_path_tiles'][1:]] for p in panes[:2])
assert all(abs(x - y) < 0.04 for x, y in zip(a, b)), (a, b)
PY
echo "ok: the light-path view (path and radiosity)"
# The checker itself must catch a wrong picture: pane 1 (shadows, one light sample a pass) is not
# the box without shadows. (It was "not the 16-sample render"; one sample a pass is unbiased, so at
# the checker's block scale the two now agree, as they should.)
if "$CHECK" "$OUT/two_panes.png" pane 1 "$OUT/no_shadows.pfm" >/dev/null; then
  echo "FAIL: the checker accepted the wrong reference"; exit 1
fi
echo "GUI screenshots OK: $OUT"
