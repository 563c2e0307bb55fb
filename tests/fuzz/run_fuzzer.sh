#!/usr/bin/env bash
# Usage: run_fuzzer.sh [--campaign] TARGET FUZZER AMOUNT WORKDIR
# Runs libFuzzer target TARGET (scene_json, obj_scene, command_line).
#
# Default (CI): deterministic. First every saved regression input
# (tests/fuzz/regressions/TARGET/) is replayed; then AMOUNT inputs are run
# from a fresh seed corpus made from data/, with a fixed seed. The same code
# explores the same inputs on every run, so CI fails only on a change, never
# on a new random find.
#
# --campaign: a longer random search, outside CI. Runs for AMOUNT seconds with
# a random seed, keeps WORKDIR/corpus between runs (a campaign continues where
# the last one stopped). A crash is saved as WORKDIR/artifacts/crash-*: fix it
# and keep the input in tests/fuzz/regressions/TARGET/.
#
# Fails on any finding; the input that caused it is WORKDIR/artifacts/*.
set -euo pipefail
campaign=0
if [ "${1:-}" = --campaign ]; then campaign=1; shift; fi
target=$1; fuzzer=$(realpath "$2"); amount=$3; work=$(realpath -m "$4")
root=$(cd "$(dirname "$0")/../.." && pwd)
corpus=$work/corpus
[ $campaign = 0 ] && rm -rf "$corpus"  # deterministic: the seeds, not what earlier runs added
mkdir -p "$corpus" "$work/artifacts"
# The targets' scratch folders (fuzz_support.h) go under WORKDIR, not into /tmp for good.
export TMPDIR=$work/tmp
rm -rf "$TMPDIR" && mkdir -p "$TMPDIR"
case "$target" in
  scene_json)
    cp "$root"/data/scenes/*.json "$root"/data/scenes/tests/*.json "$root"/data/scenes/tests/bad/*.json "$corpus"/
    rm -f "$corpus/scene.schema.json" ;;
  obj_scene)
    cp "$root/data/scenes/tests/obj_scene/cube.obj" "$corpus/cube_alone.obj"
    # The OBJ naming m.mtl, then the marker line, then the MTL (see obj_scene_fuzzer.cpp).
    { sed 's/^mtllib .*/mtllib m.mtl/' "$root/data/scenes/tests/obj_scene/cube.obj"; printf '\n#MTL\n';
      cat "$root/data/scenes/tests/obj_scene/cube.mtl"; } > "$corpus/cube_with_mtl.obj"
    # The bunny's first vertices and faces as OBJ text: real coordinates, real connectivity.
    python3 - "$root/data/meshes/bunny.ply" "$corpus/bunny_part.obj" <<'PY'
import sys
data = open(sys.argv[1], 'rb').read()
header, _, body = data.partition(b'end_header\n')
lines = header.decode().splitlines()
if 'format ascii' not in header.decode():
    open(sys.argv[2], 'w').write('v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n'); sys.exit()
rows = body.decode().splitlines()
nv = int([l for l in lines if l.startswith('element vertex')][0].split()[2])
out = ['v ' + ' '.join(r.split()[:3]) for r in rows[:200]]
for r in rows[nv:nv + 2000]:
    idx = [int(x) + 1 for x in r.split()[1:4]]
    if max(idx) <= 200: out.append('f ' + ' '.join(map(str, idx)))
open(sys.argv[2], 'w').write('\n'.join(out) + '\n')
PY
    ;;
  command_line)
    n=0
    while IFS= read -r line; do
      n=$((n + 1)); printf '%s' "$line" | tr ' ' '\n' > "$corpus/seed_$n"
    done < "$root/tests/fuzz/command_line_seeds.txt" ;;
  *) echo "unknown fuzz target '$target' (allowed: scene_json, obj_scene, command_line)" >&2; exit 2 ;;
esac
cd "$work"
# -timeout: an input taking 25 s is a hang; -rss_limit_mb: one taking 2 GB is a runaway allocation.
limits=(-timeout=25 -rss_limit_mb=2048 -artifact_prefix="$work/artifacts/")
regressions=("$root/tests/fuzz/regressions/$target"/*)
if [ -e "${regressions[0]}" ]; then
  echo "replaying ${#regressions[@]} regression inputs of $target"
  "$fuzzer" "${limits[@]}" "${regressions[@]}"
fi
if [ $campaign = 1 ]; then
  exec "$fuzzer" -max_total_time="$amount" -print_final_stats=1 "${limits[@]}" "$corpus"
fi
# A fixed number of runs from a fixed seed; the time cap only guards a very slow machine (it can cut
# the list short, never change it).
exec "$fuzzer" -seed=1 -runs="$amount" -max_total_time=240 -print_final_stats=1 "${limits[@]}" "$corpus"
