#!/usr/bin/env bash
# lightlab study writes a CSV whose error falls as the knob buys accuracy,
# and a self-contained HTML page with the plot. Usage: study_test.sh LIGHTLAB OUTDIR
set -euo pipefail
lightlab=${1:?usage: study_test.sh LIGHTLAB OUTDIR} out=${2:?}
root=$(cd "$(dirname "$0")/../.." && pwd)
rm -rf "$out"
"$lightlab" --quiet study "$root/data/scenes/cornell_box.json" --knob light_samples=1,4,16,64 -t raycast \
  --set intersection=framework --reference-set light_samples=1024 --width 64 --out "$out" > "$out.txt"
python3 - "$out/study.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert [r["light_samples"] for r in rows] == ["1", "4", "16", "64"], rows
err = [float(r["relmse"]) for r in rows]
assert all(a > b for a, b in zip(err, err[1:])), f"the error does not fall: {err}"
assert err[-1] < err[0] / 20, err
assert all(float(r["seconds"]) > 0 for r in rows)
print("study: relMSE", " > ".join(f"{e:.3g}" for e in err))
PY
grep -q "<svg" "$out/study.html" && grep -q "data:image/png;base64," "$out/study.html" || { echo "FAIL: study.html lacks the plot or the images"; exit 1; }
[ -s "$out/reference.pfm" ] || { echo "FAIL: no reference.pfm"; exit 1; }

# The built-in ground-truth study: path tracing's error falls with the samples; ray casting and Whitted
# plateau above it (the Cornell box's interreflection is what they miss); radiosity gets close.
"$lightlab" --quiet study ground-truth --width 24 --reference-spp 1024 --cache "" --out "$out/truth" > "$out.truth.txt"
python3 - "$out/truth/study.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
err = {(r["technique"], r["spp"]): float(r["relmse"]) for r in rows}
path = [err[("path", s)] for s in ("1", "4", "16", "64")]
assert all(a > b for a, b in zip(path, path[1:])), f"path tracing's error does not fall: {path}"
for t in ("raycast", "whitted"):
    assert err[(t, "64")] > 3 * err[("path", "64")], f"{t} does not miss what path tracing sees: {err}"
assert err[("radiosity", "64")] < err[("raycast", "64")], err
print("ground truth: relMSE at 64 spp", {t: round(err[(t, "64")], 4) for t in ("raycast", "whitted", "radiosity", "path")})
PY
