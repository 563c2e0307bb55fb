#!/usr/bin/env bash
# Writes the student tree: the project without a line of solution.
#   - every file but those of assignments/instructor_only.txt (planted bugs,
#     alternative solutions, the framework's own answers to tasks, this script);
#   - every solution region cut out by Debian's unifdef:
#       #if LIGHTLAB_SOLUTION  // A2.4 ... #else <stub> #endif    -> the stub
#       #if !LIGHTLAB_STUDENT_TREE  // A2.3's answer ... #endif   -> nothing
#   - the references as object code only, in assignments/reference/lib: each
#     task's solution as a module (lightlab_<ID>.so, what --reference and the
#     grader run) and the framework's answers (liblightlab_private.a), built
#     by the solution tree's build;
#   - the build defaulting to the student configuration (LIGHTLAB_SOLUTION OFF).
#
# Usage: assignments/make_student_tree.sh OUTDIR [SOLUTION_BUILD_DIR]
#   SOLUTION_BUILD_DIR  the solution tree's build folder (default build/; configured
#                       and built here if needed: only the reference targets)
set -euo pipefail
out=${1:?usage: make_student_tree.sh OUTDIR [SOLUTION_BUILD_DIR]}
root=$(cd "$(dirname "$0")/.." && pwd)
build=${2:-$root/build}
command -v unifdef >/dev/null || { echo "make_student_tree: unifdef is not installed (apt-get install unifdef)" >&2; exit 2; }
[ -e "$out" ] && [ -n "$(ls -A "$out" 2>/dev/null)" ] && { echo "make_student_tree: $out exists and is not empty" >&2; exit 2; }

# The references, from the solution build.
if [ ! -f "$build/CMakeCache.txt" ]; then
  generator=()
  command -v ninja >/dev/null && generator=(-G Ninja)
  cmake -S "$root" -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
grep -q '^LIGHTLAB_SOLUTION:BOOL=ON' "$build/CMakeCache.txt" ||
  { echo "make_student_tree: $build is not a solution build (LIGHTLAB_SOLUTION=ON)" >&2; exit 2; }
cmake --build "$build" --target lightlab_reference_modules >/dev/null

mkdir -p "$out"
out=$(cd "$out" && pwd)

# Copy what git tracks (or, outside a checkout, everything but build folders), minus the manifest.
python3 - "$root" "$out" <<'PY'
import fnmatch, os, re, shutil, subprocess, sys
root, out = sys.argv[1], sys.argv[2]
def git(*args):
    return subprocess.run(["git", "-C", root, *args], check=True, capture_output=True).stdout.decode()
try:
    if os.path.realpath(git("rev-parse", "--show-toplevel").strip()) != os.path.realpath(root):
        raise FileNotFoundError("not the root of a checkout")  # e.g. a tarball unpacked inside another repository
    listed = git("ls-files", "-z", "--cached", "--others", "--exclude-standard").split("\0")
    files = [f for f in listed if f and os.path.isfile(os.path.join(root, f))]
except (subprocess.CalledProcessError, FileNotFoundError):
    files = []
    for d, dirs, names in os.walk(root):
        rel = os.path.relpath(d, root)
        dirs[:] = [x for x in dirs if not (rel == "." and (x.startswith("build") or x in (".git", "out")))]
        files += [os.path.normpath(os.path.join(rel, n)) for n in names]
patterns = [l.strip() for l in open(os.path.join(root, "assignments/instructor_only.txt"))
            if l.strip() and not l.startswith("#")]
def withheld(f):
    return any(fnmatch.fnmatchcase(f, p) or (p.endswith("/**") and f.startswith(p[:-2])) for p in patterns)
kept = [f for f in files if not withheld(f)]
for f in kept:
    os.makedirs(os.path.dirname(os.path.join(out, f)) or out, exist_ok=True)
    shutil.copy2(os.path.join(root, f), os.path.join(out, f))
print(f"copied {len(kept)} files, withheld {len(files) - len(kept)}")
PY

# Cut the solution regions from every C++ file of the framework and the assignments.
count=0
while IFS= read -r -d '' f; do
  if grep -q 'LIGHTLAB_SOLUTION\|LIGHTLAB_STUDENT_TREE' "$f"; then
    unifdef -x 2 -DLIGHTLAB_SOLUTION=0 -DLIGHTLAB_STUDENT_TREE=1 -o "$f.tmp" "$f" && mv "$f.tmp" "$f"
    count=$((count + 1))
  fi
done < <(find "$out/framework" "$out/assignments" \( -name '*.cpp' -o -name '*.h' \) ! -name 'a[0-9]_test.cpp' -print0)
if grep -rnE --include='*.cpp' --include='*.h' '^#if (LIGHTLAB_SOLUTION|!LIGHTLAB_STUDENT_TREE)' \
     "$out/framework" "$out/assignments"; then
  echo "make_student_tree: solution regions left behind (above)" >&2
  exit 1
fi

# The references as object code.
lib="$out/assignments/reference/lib"
mkdir -p "$lib"
cp "$build"/modules/reference/lightlab_*.so "$build"/modules/reference/liblightlab_private.a "$lib/"
cat > "$out/assignments/reference/README.md" <<'README'
# The references, as object code

`lib/lightlab_<ID>.so` is the course's solution of task ID, compiled; `lib/liblightlab_private.a`
holds the framework's own code that would answer a task (the watertight triangle test, the
reference camera, ...). The build links them and runs a task's reference wherever your code is a
stub, or where you ask for it: `build/lightlab --reference A2.3,A2.5 render ...`, the task switches
in the GUI's side panel. The tests of one task run every other task by its reference, so each task
can be done, tested and graded on its own. Your code cannot call them: a task's code that uses the
framework's answer to that task is reported, and fails its tests.
README

sed -i 's/^option(LIGHTLAB_SOLUTION \(".*"\) ON)/option(LIGHTLAB_SOLUTION \1 OFF)/' "$out/CMakeLists.txt"
grep -q 'option(LIGHTLAB_SOLUTION .* OFF)' "$out/CMakeLists.txt" || { echo "make_student_tree: could not flip LIGHTLAB_SOLUTION" >&2; exit 1; }

# The top README's command that makes this tree: the script is the instructor's, not in this tree.
sed -i '/^# Make the student tree:/,/^bash assignments\/make_student_tree.sh/d' "$out/README.md"
if grep -q '^bash assignments/make_student_tree.sh' "$out/README.md"; then
  echo "make_student_tree: the README's make_student_tree command is still in the student tree" >&2
  exit 1
fi

cat > "$out/NOTICE-STUDENTS.md" <<'NOTICE'
# For students

This is the LightLab student tree. Every task you are to write is a stub that
reports "Ax.y not implemented"; until you write it, the task's reference (the
course's solution, as object code in `assignments/reference/lib`) stands in,
and the pixels it touched are striped magenta. The handouts are in
`assignments/*/README.md`.

Your solutions are your own course work: do not post them publicly (no public
repositories, gists or forums). Keep your repository private.
NOTICE
echo "student tree written to $out ($count sources stripped; references in assignments/reference/lib)"
