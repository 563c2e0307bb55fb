#!/usr/bin/env bash
# Writes the student tree: the whole project with every solution region
#   #if LIGHTLAB_SOLUTION  // A2.4 ...  <solution>  #else  <stub>  #endif
# replaced by its stub (Debian's unifdef does the cutting), the build
# defaulting to the stubs, and a notice about sharing. Tests stay intact so
# students can check themselves; they fail with "A2.x not implemented".
#
# Usage: assignments/make_student_tree.sh OUTDIR
set -euo pipefail
out=${1:?usage: make_student_tree.sh OUTDIR}
root=$(cd "$(dirname "$0")/.." && pwd)
command -v unifdef >/dev/null || { echo "make_student_tree: unifdef is not installed (apt-get install unifdef)" >&2; exit 2; }
[ -e "$out" ] && [ -n "$(ls -A "$out" 2>/dev/null)" ] && { echo "make_student_tree: $out exists and is not empty" >&2; exit 2; }
mkdir -p "$out"
out=$(cd "$out" && pwd)

# Copy what git tracks (or, outside a checkout, everything but build folders).
if git -C "$root" rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  (cd "$root" && git ls-files -z --cached --others --exclude-standard | xargs -0 cp --parents -t "$out")
else
  (cd "$root" && tar --exclude='./build*' --exclude='./.git' -cf - .) | (cd "$out" && tar -xf -)
fi

# Cut the solutions from assignment sources (tests keep their own guards).
count=0
while IFS= read -r -d '' f; do
  unifdef -x 2 -DLIGHTLAB_SOLUTION=0 -o "$f.tmp" "$f" && mv "$f.tmp" "$f"
  count=$((count + 1))
done < <(find "$out/assignments" \( -name '*.cpp' -o -name '*.h' \) ! -name '*_test.cpp' -print0)

if grep -rn --include='*.cpp' --include='*.h' --exclude='*_test.cpp' '^#if LIGHTLAB_SOLUTION' "$out/assignments"; then
  echo "make_student_tree: solution regions left behind (above)" >&2
  exit 1
fi
sed -i 's/^option(LIGHTLAB_SOLUTION \(".*"\) ON)/option(LIGHTLAB_SOLUTION \1 OFF)/' "$out/CMakeLists.txt"
grep -q 'option(LIGHTLAB_SOLUTION .* OFF)' "$out/CMakeLists.txt" || { echo "make_student_tree: could not flip LIGHTLAB_SOLUTION" >&2; exit 1; }

cat > "$out/NOTICE-STUDENTS.md" <<'NOTICE'
# For students

This is the LightLab student tree. Every task you are to write is a stub that
reports "Ax.y not implemented" and keeps the rest of the program running; the
handouts are in `assignments/*/README.md`.

Your solutions are your own course work: do not post them publicly (no public
repositories, gists or forums). Keep your repository private.
NOTICE
echo "student tree written to $out ($count assignment sources stripped)"
