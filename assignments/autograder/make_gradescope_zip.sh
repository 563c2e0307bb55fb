#!/usr/bin/env bash
# Packs the zip Gradescope's "Autograder" setting takes, for one assignment:
#   setup.sh        installs and builds the student tree's framework (setup_autograder.sh)
#   run_autograder  grades /autograder/submission into /autograder/results (run_autograder)
#   the student tree itself, with a fresh secret seed for the tests' random inputs
#   (assignments/autograder/secret_seed: in the zip only, never in the student tree).
# Gradescope unpacks the zip into /autograder/source and runs setup.sh there once.
#
# Usage: assignments/autograder/make_gradescope_zip.sh ASSIGNMENT OUT.zip
#   run from a student tree (assignments/make_student_tree.sh makes one).
set -euo pipefail
assignment=${1:?usage: make_gradescope_zip.sh ASSIGNMENT OUT.zip}
out=${2:?usage: make_gradescope_zip.sh ASSIGNMENT OUT.zip}
root=$(cd "$(dirname "$0")/../.." && pwd)
[ -f "$root/assignments/reference/lib/liblightlab_private.a" ] ||
  { echo "make_gradescope_zip: run it from a student tree (assignments/make_student_tree.sh)" >&2; exit 2; }
grep -qil "\"assignment\": \"$assignment\"" "$root"/assignments/*/grading.json ||
  { echo "make_gradescope_zip: unknown assignment $assignment" >&2; exit 2; }
python3 - "$root" "$assignment" "$out" <<'PY'
import os, secrets, sys, zipfile
root, assignment, out = sys.argv[1:4]
def add(z, path, arcname, text=None, mode=0o644):
    info = zipfile.ZipInfo(arcname)
    info.external_attr = (0o100000 | mode) << 16
    info.compress_type = zipfile.ZIP_DEFLATED
    data = text.encode() if text is not None else open(path, "rb").read()
    z.writestr(info, data)
with zipfile.ZipFile(out, "w") as z:
    add(z, None, "setup.sh", "#!/usr/bin/env bash\n# Gradescope: install and build once, in /autograder/source.\n"
        "set -euo pipefail\ncd /autograder/source\nbash assignments/autograder/setup_autograder.sh\n", 0o755)
    add(z, None, "run_autograder", "#!/usr/bin/env bash\n# Gradescope: grade one submission of " + assignment + ".\n"
        "exec bash /autograder/source/assignments/autograder/run_autograder " + assignment +
        " /autograder/submission /autograder/results\n", 0o755)
    add(z, None, "assignments/autograder/secret_seed", str(secrets.randbelow(2**31 - 2) + 2) + "\n", 0o600)
    for d, dirs, files in os.walk(root):
        rel = os.path.relpath(d, root)
        dirs[:] = sorted(x for x in dirs if not (rel == "." and (x.startswith("build") or x in (".git", "out"))))
        for f in sorted(files):
            p = os.path.join(d, f)
            arc = os.path.normpath(os.path.join(rel, f))
            if arc == "assignments/autograder/secret_seed": continue
            add(z, p, arc, mode=0o755 if os.access(p, os.X_OK) else 0o644)
print(f"wrote {out}: {assignment} (setup.sh, run_autograder, the student tree, a new secret seed)")
PY
