#!/usr/bin/env bash
# The Gradescope zip of the student tree: setup.sh and run_autograder at its
# root, the tree itself, and a secret seed that the student tree does not hold.
# Usage: gradescope_zip_test.sh STUDENT_TREE WORKDIR
set -euo pipefail
tree=${1:?usage: gradescope_zip_test.sh STUDENT_TREE WORKDIR}
work=${2:?}
rm -rf "$work"
mkdir -p "$work"
bash "$tree/assignments/autograder/make_gradescope_zip.sh" A2 "$work/a2.zip"
python3 - "$work/a2.zip" "$tree" <<'PY'
import os, stat, sys, zipfile
z = zipfile.ZipFile(sys.argv[1])
names = set(z.namelist())
for need in ("setup.sh", "run_autograder", "assignments/autograder/secret_seed", "assignments/autograder/run_autograder",
             "assignments/reference/lib/liblightlab_private.a", "assignments/a2_raycasting/grading.json", "CMakeLists.txt"):
    assert need in names, f"FAIL: the zip has no {need}"
for exe in ("setup.sh", "run_autograder"):
    assert z.getinfo(exe).external_attr >> 16 & stat.S_IXUSR, f"FAIL: {exe} is not executable in the zip"
assert not any(n.startswith("build/") for n in names), "FAIL: the zip holds a build folder"
seed = z.read("assignments/autograder/secret_seed").decode().strip()
assert seed.isdigit() and seed != "1", f"FAIL: secret seed {seed!r}"
assert not os.path.exists(os.path.join(sys.argv[2], "assignments/autograder/secret_seed")), "FAIL: the student tree holds the seed"
assert "run_autograder A2 /autograder/submission /autograder/results" in z.read("run_autograder").decode()
print(f"gradescope zip: {len(names)} files, setup.sh and run_autograder at the root, a secret seed")
PY
