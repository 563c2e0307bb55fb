#!/usr/bin/env bash
# The built student tree runs: renders name every missing task and stripe its
# pixels while the references stand in (the same picture where the reference is
# exact), the GUI under Xvfb names the missing tasks in its panes (and measures a
# striped pane's error on its radiance, not its stripes), --reference
# gives the solution's picture, and grading every assignment scores 0 with each
# task "not implemented", without a crash.
# Usage: runs_test.sh STUDENT_TREE WORKDIR
set -euo pipefail
tree=${1:?usage: runs_test.sh STUDENT_TREE WORKDIR}
work=${2:?}
rm -rf "$work"
mkdir -p "$work"
build="$tree/build"
cd "$tree"
missing() {  # STDERR_FILE TASK...: each task is reported as not implemented
  local f=$1
  shift
  for task in "$@"; do
    grep -q "$task not implemented" "$f" || { cat "$f"; echo "FAIL: $task is not reported as missing"; exit 1; }
  done
}
build/lightlab --quiet render data/scenes/cornell_box.json --width 96 -o "$work/out.png" 2>"$work/a2.txt"
missing "$work/a2.txt" A2.1 A2.3 A2.4 A2.5
[ -s "$work/out.png" ] || { echo "FAIL: no image written"; exit 1; }
build/lightlab --quiet render data/scenes/tests/two_spheres_materials.json -o "$work/out2.png" 2>"$work/a2b.txt"
missing "$work/a2b.txt" A2.2 A2.3
# The references stand in where the stubs run: with every A2 task by its reference, the solution's picture.
build/lightlab --quiet --reference A2 render data/scenes/cornell_box.json --width 64 -o "$work/ref.pfm" 2>"$work/ref.txt"
if grep -q 'not implemented' "$work/ref.txt"; then cat "$work/ref.txt"; echo "FAIL: --reference A2 still ran a stub"; exit 1; fi
grep -q 'by their reference (--reference): A2.1,A2.2,A2.3,A2.4,A2.5' "$work/ref.txt" ||
  { cat "$work/ref.txt"; echo "FAIL: the render does not say which tasks ran by their reference"; exit 1; }
# A4: the accelerators' stubs: the reference traversal answers, the same picture as brute force, no stripes.
build/lightlab --quiet render data/scenes/bunny.json -a none --width 48 --set intersection=framework -o "$work/none.pfm" 2>/dev/null
for pair in bvh:A4.2 kdtree:A4.3 octree:A4.4 bsp:A4.5; do
  accel=${pair%%:*} task=${pair##*:}
  build/lightlab --quiet render data/scenes/bunny.json -a "$accel" --width 48 --set intersection=framework \
    -o "$work/$accel.pfm" 2>"$work/$accel.txt"
  missing "$work/$accel.txt" "$task"
  cmp -s "$work/$accel.pfm" "$work/none.pfm" || { echo "FAIL: the $task reference changed the picture"; exit 1; }
done
build/lightlab --quiet render data/scenes/textured_floor.json -t blinn-phong --width 96 -o "$work/a1.png" 2>"$work/a1.txt"
missing "$work/a1.txt" A1.1 A1.2 A1.3 A1.4 A1.5
build/lightlab --quiet render data/scenes/whitted_1980.json -t whitted -a bvh --width 96 --height 72 -o "$work/a3.png" \
  2>"$work/a3.txt"
missing "$work/a3.txt" A3.4
# trace says the same of the ray tree it prints.
build/lightlab trace data/scenes/whitted_1980.json --pixel 380 200 -t whitted -a bvh >/dev/null 2>"$work/trace.txt"
missing "$work/trace.txt" A3.1 A3.2 A3.3 A3.4 A3.5
for pair in "form_factors=analytic:A5.1" "solver=gauss-seidel:A5.2" "solver=southwell:A5.3"; do
  set_arg=${pair%%:*} task=${pair##*:}
  build/lightlab --quiet radiosity data/scenes/cornell_box.json --set patch_size=0.2 --set hemicube_res=8 \
    --set "$set_arg" >/dev/null 2>"$work/a5.txt"
  missing "$work/a5.txt" "$task"
done
build/lightlab --quiet render data/scenes/cornell_box.json -t path --width 32 --height 32 --spp 2 --set max_depth=3 \
  -o "$work/a6.png" 2>"$work/a6.txt"
missing "$work/a6.txt" A6.1 A6.2 A6.3
# A6.4 (GGX) runs only for rough metals and rough glass, which the Cornell box has none of.
build/lightlab --quiet render data/scenes/metal_spheres.json -t path --width 32 --height 18 --spp 2 --set max_depth=3 \
  -o "$work/a6_metals.png" 2>"$work/a6_metals.txt"
missing "$work/a6_metals.txt" A6.4
# Grading the untouched tree: every task "not implemented", 0 points, a normal exit.
for a in A1 A2 A3 A4 A5 A6; do
  build/lightlab --quiet grade "$a" --format text,gradescope --report "$work/grade/$a" > "$work/grade_$a.txt" 2>&1 ||
    { cat "$work/grade_$a.txt"; echo "FAIL: grading $a in the student tree exited with $?"; exit 1; }
  python3 - "$work/grade/$a/results.json" "$a" "$work/grade_$a.txt" <<'PY' || { cat "$work/grade_$a.txt"; exit 1; }
import json, re, sys
d = json.load(open(sys.argv[1]))
if d["score"] != 0:
    sys.exit(f"FAIL: the student tree scores {d['score']} on {sys.argv[2]}")
rows = [l.split() for l in open(sys.argv[3]) if re.match(r"\s+A\d\.\d\s", l)]
wrong = [r[0] for r in rows if " ".join(r[-2:]) != "not implemented"]
if not rows or wrong:
    sys.exit(f"FAIL: {sys.argv[2]}: tasks not reported as not implemented: {wrong or 'no task rows'}")
print(f"{sys.argv[2]}: 0 points, {len(rows)} tasks not implemented")
PY
done
if command -v xvfb-run >/dev/null && build/lightlab --help | grep -q '^\s*gui'; then
  xvfb-run -a -n 170 -s '-noreset -screen 0 1280x800x24' build/lightlab gui --preset tests/gui/two_panes.json \
    --screenshot "$work/gui.png" --frames 3 --timeout 600 >/dev/null
  for task in A2.1 A2.4 A2.5; do
    grep -q "\"$task\"" "$work/gui.json" || { echo "FAIL: the GUI pane does not name $task as missing"; exit 1; }
  done
  grep -q '"phase": "done"' "$work/gui.json" || { echo "FAIL: the GUI panes did not finish"; exit 1; }
  # A pane's error against the reference pane measures radiance, not the stripes that mark a stub:
  # A5's radiosity with its two stubs (the reference answering, striped) against the path tracer.
  xvfb-run -a -n 171 -s '-noreset -screen 0 1280x800x24' build/lightlab gui --assignment A5 \
    --screenshot "$work/gui_a5.png" --frames 3 --timeout 600 >/dev/null
  python3 - "$work/gui_a5.json" <<'PY'
import json, sys
a = json.load(open(sys.argv[1]))["panes"][0]
if a["technique"] != "radiosity" or not a["striped"]:
    sys.exit(f"FAIL: A5's pane A is {a['technique']}, striped {a['striped']}: expected radiosity with stub stripes")
e = a["vs_reference"]
if e is None or not e["relmse"] < 0.1:  # about 0.02 (16 spp of noise); 11 when the stripes were measured
    sys.exit(f"FAIL: A5's pane A against the path tracer: {e} (relMSE of the stripes, not of the radiance?)")
print(f"GUI A5: pane A striped, relMSE {e['relmse']:.3f} against the path tracer")
PY
fi
echo "student tree: runs; the references stand in for every stub and each is named (CLI, GUI); grades to 0"
