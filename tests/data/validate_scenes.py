#!/usr/bin/env python3
"""Check the bundled scene files against data/scenes/scene.schema.json.

    python3 tests/data/validate_scenes.py [REPO_ROOT]

Every *.json under data/scenes (except the schema itself and data/scenes/tests/bad/) must
parse, validate against the schema and pass the checks a schema cannot express (material
names defined, referenced files present, indices in range, ...).

Every file in data/scenes/tests/bad/ must be rejected: malformed_json.json by the JSON
parser; missing_mesh.json and unknown_material.json must pass the schema and be caught by
the extra checks (so they exercise the loader's own checks); all others must fail the schema.

Prints one line per file and "N passed, M failed"; exits 1 on any failure.
Needs python3-jsonschema (Debian) >= 4.0 for draft 2020-12.
"""
import json
import math
import sys
from pathlib import Path

try:
    import jsonschema
except ImportError:  # pragma: no cover
    print("python3-jsonschema is not installed (apt-get install python3-jsonschema)")
    sys.exit(1)

# bad/ files that are valid for the schema and must be caught by the semantic checks
SEMANTIC_ONLY = {"missing_mesh.json", "unknown_material.json"}
# bad/ files that are not even valid JSON
SYNTAX_ONLY = {"malformed_json.json"}
# bad/ files that must exist
EXPECTED_BAD = SEMANTIC_ONLY | SYNTAX_ONLY | {
    "unknown_key.json", "wrong_type.json", "negative_radius.json"}


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def length(a):
    return math.sqrt(sum(x * x for x in a))


def schema_errors(validator, scene):
    errors = sorted(validator.iter_errors(scene), key=lambda e: list(e.absolute_path))
    out = []
    for e in errors:
        best = jsonschema.exceptions.best_match([e])
        where = "/".join(str(p) for p in best.absolute_path) or "(top level)"
        out.append(f"{where}: {best.message}")
    return out


def semantic_errors(scene, scene_path: Path):
    """Checks the schema cannot express. Assumes the scene is schema-valid."""
    errs = []
    base = scene_path.parent
    cam = scene["camera"]
    fwd = sub(cam["target"], cam["eye"])
    if length(fwd) == 0:
        errs.append("camera: eye and target coincide")
    elif length(cross(fwd, cam.get("up", [0, 1, 0]))) < 1e-9 * length(fwd):
        errs.append("camera: up is parallel to the view direction (or zero)")
    materials = scene["materials"]
    for name, m in materials.items():
        tex = m.get("texture")
        if isinstance(tex, str) and not (base / tex).is_file():
            errs.append(f"materials/{name}/texture: file not found: {tex}")
    for i, light in enumerate(scene.get("lights", [])):
        if light["type"] == "directional" and length(light["direction"]) == 0:
            errs.append(f"lights/{i}/direction: zero vector")
    for i, o in enumerate(scene["objects"]):
        where = f"objects/{i}" + (f" ({o['name']})" if "name" in o else "")
        if o["material"] not in materials:
            errs.append(f"{where}: material '{o['material']}' is not defined")
        t = o["type"]
        if t == "mesh" and not (base / o["file"]).is_file():
            errs.append(f"{where}: mesh file not found: {o['file']}")
        if t == "triangles":
            n = len(o["positions"])
            for k, tri in enumerate(o["indices"]):
                if any(j >= n for j in tri):
                    errs.append(f"{where}/indices/{k}: index out of range (positions: {n})")
            for key in ("normals", "uvs"):
                if key in o and len(o[key]) != n:
                    errs.append(f"{where}/{key}: {len(o[key])} entries for {n} positions")
        if t in ("quad", "polygon"):
            v = o["vertices"]
            nrm = cross(sub(v[1], v[0]), sub(v[2], v[0]))
            size = max(length(sub(p, v[0])) for p in v)
            if length(nrm) <= 1e-12 * size * size:
                errs.append(f"{where}: first three vertices are collinear")
            else:
                unit = [c / length(nrm) for c in nrm]
                off = max(abs(sum(unit[k] * sub(p, v[0])[k] for k in range(3))) for p in v)
                if off > 1e-6 * size:
                    errs.append(f"{where}: not planar ({off:g} off the plane); use 'triangles'")
    return errs


def check_obj(path: Path):
    errs = []
    for line in path.read_text().splitlines():
        parts = line.split()
        if parts and parts[0] == "mtllib":
            for lib in parts[1:]:
                if not (path.parent / lib).is_file():
                    errs.append(f"mtllib not found: {lib}")
    return errs


def main() -> int:
    root = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).resolve().parents[2]
    scenes = root / "data" / "scenes"
    schema_path = scenes / "scene.schema.json"
    bad_dir = scenes / "tests" / "bad"
    schema = json.loads(schema_path.read_text())
    jsonschema.Draft202012Validator.check_schema(schema)
    validator = jsonschema.Draft202012Validator(schema)
    passed = failed = 0

    def report(ok, rel, msg):
        nonlocal passed, failed
        if ok:
            passed += 1
            print(f"PASS {rel}{': ' + msg if msg else ''}")
        else:
            failed += 1
            print(f"FAIL {rel}: {msg}")

    good = sorted(p for p in scenes.rglob("*.json")
                  if p != schema_path and bad_dir not in p.parents)
    for path in good:
        rel = path.relative_to(root)
        try:
            scene = json.loads(path.read_text())
        except json.JSONDecodeError as e:
            report(False, rel, f"invalid JSON: {e}")
            continue
        errs = schema_errors(validator, scene)
        if not errs:
            errs = semantic_errors(scene, path)
        report(not errs, rel, "; ".join(errs[:5]))

    for path in sorted(scenes.rglob("*.obj")):
        errs = check_obj(path)
        report(not errs, path.relative_to(root), "; ".join(errs))

    present = {p.name for p in bad_dir.glob("*.json")}
    for name in sorted(EXPECTED_BAD - present):
        report(False, (bad_dir / name).relative_to(root), "expected bad scene is missing")
    for path in sorted(bad_dir.glob("*.json")):
        rel = path.relative_to(root)
        try:
            scene = json.loads(path.read_text())
        except json.JSONDecodeError as e:
            ok = path.name in SYNTAX_ONLY
            report(ok, rel, f"rejected as expected (JSON: {e})" if ok
                   else f"should be valid JSON but is not: {e}")
            continue
        if path.name in SYNTAX_ONLY:
            report(False, rel, "should be malformed JSON but parses")
            continue
        errs = schema_errors(validator, scene)
        if path.name in SEMANTIC_ONLY:
            if errs:
                report(False, rel, "should pass the schema (only the loader catches it): "
                       + "; ".join(errs))
                continue
            sem = semantic_errors(scene, path)
            report(bool(sem), rel, ("rejected as expected (loader check: "
                                    + "; ".join(sem) + ")") if sem
                   else "should fail the loader's checks but passes")
        else:
            report(bool(errs), rel, ("rejected as expected (schema: " + "; ".join(errs) + ")")
                   if errs else "should fail the schema but passes")

    print(f"{passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
