#!/usr/bin/env bash
# The solution scores full marks on every assignment, whatever the thread
# count and the seed. Usage: grade_solution_test.sh LIGHTLAB WORKDIR THREADS SEED
set -euo pipefail
lightlab=${1:?usage: grade_solution_test.sh LIGHTLAB WORKDIR THREADS SEED}
work=${2:?} threads=${3:?} seed=${4:?}
rm -rf "$work"
mkdir -p "$work"
work=$(cd "$work" && pwd)
# The report folder relative to the working directory, as a student names it (the default,
# out/grade/A2, is relative too): the renders run in a folder of their own and must not
# resolve their paths against it.
cd "$(dirname "$work")"
for a in A1 A2 A3 A4 A5 A6; do
  "$lightlab" --quiet --threads "$threads" grade "$a" --seed "$seed" --format text,gradescope,junit,html \
    --report "$(basename "$work")/$a" > "$work.$a.txt" 2>&1 || { cat "$work.$a.txt"; echo "FAIL: grading $a exited with an error"; exit 1; }
  python3 - "$work/$a/results.json" "$a" <<'PY' || { cat "$work.$a.txt"; exit 1; }
import json, sys
d = json.load(open(sys.argv[1]))
best = sum(t["max_score"] for t in d["tests"])
failed = [t["name"] + ": " + t["output"].splitlines()[0] for t in d["tests"] if t["status"] != "passed"]
if failed or abs(d["score"] - best) > 1e-3:
    sys.exit(f"FAIL: the solution of {sys.argv[2]} scores {d['score']} of {best}:\n  " + "\n  ".join(failed))
print(f"{sys.argv[2]}: {d['score']:.4g}/{best:.4g} with {len(d['tests'])} tests")
PY
  for f in report.html junit.xml; do [ -s "$work/$a/$f" ] || { echo "FAIL: no $f for $a"; exit 1; }; done
done
echo "the solution scores full marks (threads $threads, seed $seed)"
