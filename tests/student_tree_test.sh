#!/usr/bin/env bash
# The student tree builds clean (warnings as errors), runs ray casting on the
# Cornell box without crashing, names every missing A2 task, marks the image,
# and writes it; its GUI (under Xvfb, when available) shows the missing tasks
# in each pane's banner and keeps running. Usage: student_tree_test.sh WORKDIR
set -euo pipefail
work=${1:?usage: student_tree_test.sh WORKDIR}
root=$(cd "$(dirname "$0")/.." && pwd)
rm -rf "$work"
bash "$root/assignments/make_student_tree.sh" "$work/tree"
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
# The build inside the tree (as build/ in the root): with CCACHE_BASEDIR set, ccache reuses the main build's objects.
export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$root}
build="$work/tree/build"
cmake -S "$work/tree" -B "$build" "${generator[@]}" "${launcher[@]}" -DLIGHTLAB_WARNINGS_AS_ERRORS=ON \
  -DLIGHTLAB_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build "$build" --target lightlab lightlab_task_tests lightlab_big_meshes -j 2 >/dev/null
status=0
"$build/lightlab" --quiet render "$work/tree/data/scenes/cornell_box.json" --width 96 -o "$work/out.png" \
  2>"$work/stderr.txt" || status=$?
cat "$work/stderr.txt"
[ "$status" -eq 0 ] || { echo "FAIL: the student build exited with $status"; exit 1; }
for task in A2.1 A2.4 A2.5; do
  grep -q "$task not implemented" "$work/stderr.txt" || { echo "FAIL: $task is not reported as missing"; exit 1; }
done
# A2.2/A2.3 are used by intersection=auto (the default) with -a none (the default) on a scene with spheres and triangles.
"$build/lightlab" --quiet render "$work/tree/data/scenes/tests/two_spheres_materials.json" -o "$work/out2.png" \
  2>"$work/stderr2.txt"
for task in A2.2 A2.3; do
  grep -q "$task not implemented" "$work/stderr2.txt" || { echo "FAIL: $task is not reported as missing"; exit 1; }
done
[ -s "$work/out.png" ] || { echo "FAIL: no image written"; exit 1; }
# A4: the BVH stubs fall back to brute force: same picture, tasks named, pixels not striped.
"$build/lightlab" --quiet render "$work/tree/data/scenes/bunny.json" -a bvh --width 48 --set intersection=framework \
  -o "$work/bvh.pfm" 2>"$work/stderr3.txt"
"$build/lightlab" --quiet render "$work/tree/data/scenes/bunny.json" -a none --width 48 --set intersection=framework \
  -o "$work/none.pfm" 2>/dev/null
for task in A4.1 A4.2; do
  grep -q "$task not implemented" "$work/stderr3.txt" || { echo "FAIL: $task is not reported as missing"; exit 1; }
done
cmp -s "$work/bvh.pfm" "$work/none.pfm" || { echo "FAIL: the A4 fallback changed the picture"; exit 1; }
# A4.3 (KD-tree traversal) and A4.4 (octree traversal): the same, with -a kdtree / -a octree.
for pair in kdtree:A4.3 octree:A4.4; do
  accel=${pair%%:*} task=${pair##*:}
  "$build/lightlab" --quiet render "$work/tree/data/scenes/bunny.json" -a "$accel" --width 48 \
    --set intersection=framework -o "$work/$accel.pfm" 2>"$work/stderr_$accel.txt"
  grep -q "$task not implemented" "$work/stderr_$accel.txt" || { echo "FAIL: $task is not reported as missing"; exit 1; }
  cmp -s "$work/$accel.pfm" "$work/none.pfm" || { echo "FAIL: the $task fallback changed the picture"; exit 1; }
done
# A1: the rasterizer runs on a textured scene; every stub is named, the picture is written and striped
# (A1.1-A1.3 fall back to the framework's code, A1.4 shades magenta, A1.5 uses the texture's mean colour).
"$build/lightlab" --quiet render "$work/tree/data/scenes/textured_floor.json" -t blinn-phong --width 96 \
  -o "$work/a1.png" 2>"$work/stderr_a1.txt"
for task in A1.1 A1.2 A1.3 A1.4 A1.5; do
  grep -q "$task not implemented" "$work/stderr_a1.txt" || { echo "FAIL: $task is not reported as missing"; exit 1; }
done
[ -s "$work/a1.png" ] || { echo "FAIL: no A1 image written"; exit 1; }
# A3: the Whitted stand-in (ray casting) runs; the recursion A3.4 is named. A3.1-A3.3 and A3.5 are reached
# only through A3.4, so they are reported once it is written (their unit tests name them before that).
"$build/lightlab" --quiet render "$work/tree/data/scenes/whitted_1980.json" -t whitted -a bvh --width 96 \
  --height 72 -o "$work/a3.png" 2>"$work/stderr_a3.txt"
grep -q "A3.4 not implemented" "$work/stderr_a3.txt" || { echo "FAIL: A3.4 is not reported as missing"; exit 1; }
[ -s "$work/a3.png" ] || { echo "FAIL: no A3 image written"; exit 1; }
# A5: radiosity runs with every stub (A5.1 under the analytic form factors, A5.2 under Gauss-Seidel, A5.3
# under Southwell) and names each; coarse patches keep the brute-force visibility of the A4 stubs quick.
for pair in "form_factors=analytic:A5.1" "solver=gauss-seidel:A5.2" "solver=southwell:A5.3"; do
  set_arg=${pair%%:*} task=${pair##*:}
  "$build/lightlab" --quiet radiosity "$work/tree/data/scenes/cornell_box.json" --set patch_size=0.2 \
    --set hemicube_res=8 --set "$set_arg" >/dev/null 2>"$work/stderr_a5.txt"
  grep -q "$task not implemented" "$work/stderr_a5.txt" || { echo "FAIL: $task is not reported as missing"; exit 1; }
done
# A6: the path tracer runs with every stub (uniform hemisphere sampling, no roulette; NEE adds nothing)
# and names each task.
"$build/lightlab" --quiet render "$work/tree/data/scenes/cornell_box.json" -t path --width 32 --height 32 \
  --spp 2 --set max_depth=3 -o "$work/a6.png" 2>"$work/stderr_a6.txt"
for task in A6.1 A6.2 A6.3; do
  grep -q "$task not implemented" "$work/stderr_a6.txt" || { echo "FAIL: $task is not reported as missing"; exit 1; }
done
[ -s "$work/a6.png" ] || { echo "FAIL: no A6 image written"; exit 1; }
# Grading the untouched student tree: every task "not implemented", 0 points, a normal exit.
for a in A1 A2 A3 A4 A5 A6; do
  "$build/lightlab" --quiet grade "$a" --format text,gradescope --report "$work/grade/$a" > "$work/grade_$a.txt" \
    2>&1 || { cat "$work/grade_$a.txt"; echo "FAIL: grading $a in the student tree exited with $?"; exit 1; }
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
# The autograder entry on the student tree: a submission that does not compile gets 0 and the compiler's
# message; the solution's A2 files (markers stripped, as a student would hand them in) get full marks.
mkdir -p "$work/sub_broken" "$work/sub_solution"
echo 'this is not C++' > "$work/sub_broken/camera_ray.cpp"
bash "$work/tree/assignments/autograder/run_autograder" A2 "$work/sub_broken" "$work/res_broken" 2>/dev/null
python3 - "$work/res_broken/results.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
assert d["score"] == 0 and "does not build" in d["output"] and "camera_ray.cpp" in d["tests"][0]["output"], d["output"]
print("autograder: a broken submission gets 0 points and the compiler's message")
PY
for f in camera_ray.cpp ray_sphere.cpp ray_triangle.cpp blinn_phong.cpp shadow_ray.cpp; do
  unifdef -x 2 -DLIGHTLAB_SOLUTION=1 -o "$work/sub_solution/$f" "$root/assignments/a2_raycasting/$f" || true
done
bash "$work/tree/assignments/autograder/run_autograder" A2 "$work/sub_solution" "$work/res_solution" >/dev/null
python3 - "$work/res_solution/results.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
best = sum(t["max_score"] for t in d["tests"])
assert best > 0 and abs(d["score"] - best) < 1e-3, f"the solution's files score {d['score']} of {best}"
print(f"autograder: the solution's A2 files score {d['score']:.4g}/{best:.4g}")
PY
if command -v xvfb-run >/dev/null; then
  (cd "$work/tree" && xvfb-run -a -s '-screen 0 1280x800x24' "$build/lightlab" gui \
     --preset tests/gui/two_panes.json --screenshot "$work/gui.png" --frames 3 --timeout 600 >/dev/null)
  for task in A2.1 A2.4 A2.5; do
    grep -q "\"$task\"" "$work/gui.json" || { echo "FAIL: the GUI pane does not name $task as missing"; exit 1; }
  done
  grep -q '"phase": "done"' "$work/gui.json" || { echo "FAIL: the GUI panes did not finish"; exit 1; }
fi
echo "student tree: grades to 0 with every task not implemented; builds, runs, reports A1.1-A1.5, A2.1-A2.5, A3.4, A4.1-A4.4, A5.1-A5.3 and A6.1-A6.3 as not implemented (CLI and GUI)"
