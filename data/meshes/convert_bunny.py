#!/usr/bin/env python3
"""Convert the npm package "bunny" (Stanford bunny) to data/meshes/bunny.ply.

Not run by the build; kept so that bunny.ply can be regenerated and checked.

    cd /tmp && npm pack bunny && tar xzf bunny-*.tgz     # unpacks to /tmp/package
    python3 data/meshes/convert_bunny.py /tmp/package data/meshes/bunny.ply

The package's index.js is `exports.positions=[[x,y,z],...];exports.cells=[[i,j,k],...]`
(JSON arrays), so it is parsed without node. Coordinates and triangle order are copied
unchanged (y is up, the base sits at y ~ 0, triangles are counter-clockwise seen from
outside). Writes ASCII PLY.
"""
import json
import re
import sys
from pathlib import Path


def load_package(pkg_dir: Path):
    meta = json.loads((pkg_dir / "package.json").read_text())
    src = (pkg_dir / "index.js").read_text()
    arrays = {}
    for name in ("positions", "cells"):
        m = re.search(r"exports\." + name + r"\s*=\s*(\[.*?\]\])", src, re.S)
        if not m:
            raise SystemExit(f"cannot find exports.{name} in {pkg_dir / 'index.js'}")
        arrays[name] = json.loads(m.group(1))
    return meta, arrays["positions"], arrays["cells"]


def fmt(x: float) -> str:
    s = f"{x:.6f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def main() -> int:
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    pkg_dir, out = Path(sys.argv[1]), Path(sys.argv[2])
    meta, pos, cells = load_package(pkg_dir)
    assert all(len(p) == 3 for p in pos)
    assert all(len(c) == 3 and all(0 <= i < len(pos) for i in c) for c in cells)
    lo = [min(p[k] for p in pos) for k in range(3)]
    hi = [max(p[k] for p in pos) for k in range(3)]
    header = [
        "ply",
        "format ascii 1.0",
        "comment Stanford Bunny. Source: Stanford 3D Scanning Repository,",
        "comment Stanford University Computer Graphics Laboratory",
        "comment (graphics.stanford.edu/data/3Dscanrep). Scan: Greg Turk and Marc Levoy, 1994.",
        f'comment Obtained via npm package "{meta["name"]}" version {meta["version"]}'
        f' by {meta.get("author", "?")}, license "{meta.get("license", "?")}" (its package.json).',
        "comment Stanford asks that the source be acknowledged; see data/meshes/README.md.",
        "comment Converted by data/meshes/convert_bunny.py: coordinates and triangles unchanged.",
        f"comment {len(cells)} triangles, {len(pos)} vertices, closed and consistently oriented;"
        " y up.",
        "comment bounding box min " + " ".join(fmt(v) for v in lo)
        + " max " + " ".join(fmt(v) for v in hi),
        f"element vertex {len(pos)}",
        "property float x",
        "property float y",
        "property float z",
        f"element face {len(cells)}",
        "property list uchar int vertex_indices",
        "end_header",
    ]
    lines = header
    lines += [" ".join(fmt(v) for v in p) for p in pos]
    lines += ["3 " + " ".join(str(i) for i in c) for c in cells]
    out.write_text("\n".join(lines) + "\n")
    print(f"wrote {out}: {len(pos)} vertices, {len(cells)} triangles, bbox {lo} .. {hi}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
