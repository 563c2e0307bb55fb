#!/usr/bin/env python3
"""The measured effects from the command line (issue 28).

  effects_test.py LIGHTLAB SCENES_DIR OUT_DIR

- `info whitted_1980.json --json`: the probe's size and time are stated; indirect diffuse light is
  present, measured with an interval around its value, a share of 0.1-5 %; whitted misses it, so at the
  default tolerance (1e-3) whitted is not within it and at 1e-2 it is the cheapest technique.
- the text output names the effects present, those called for, and the cheapest technique.
- `render -t path --set effects=measured --stats` makes info's call (the same probe seed): on the Whitted
  scene at the default tolerance the caustics are called for (bound 0.0011) and nothing is left out; at
  effects_tolerance 0.002 the caustics are left out, with the error added within the tolerance and the
  time saved stated; on the Cornell box it leaves out nothing the scene has.
"""
import json
import re
import subprocess
import sys

ll, scenes, out = sys.argv[1:4]


def run(*args):
    r = subprocess.run([ll, "--quiet", *args], capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"FAIL: lightlab {' '.join(args)} exited {r.returncode}: {r.stderr.strip()}")
    return r.stdout


whitted = f"{scenes}/whitted_1980.json"
info = json.loads(run("info", whitted, "--json", "--budget", "5"))["measured"]
probe = info["probe"]
assert probe["width"] == 128 and probe["spp"] >= 16 and probe["seconds"] > 0 and probe["seed"] == 1, probe
effects = {e["effect"]: e for e in info["effects"]}
indirect = effects["diffuse-interreflection"]
share = indirect["luminance_share"]
assert indirect["present"], indirect
assert 0.001 < share["value"] < 0.05 and share["low"] <= share["value"] <= share["high"], share
assert not effects["soft-shadows"]["present"], effects["soft-shadows"]
techniques = {t["technique"]: t for t in info["techniques"]}
assert "diffuse-interreflection" in techniques["whitted"]["misses_classes"], techniques["whitted"]
assert not techniques["whitted"]["within_tolerance"], techniques["whitted"]
assert techniques["path"]["within_tolerance"], techniques["path"]
assert info["cheapest_within_tolerance"] == "path", info["cheapest_within_tolerance"]
loose = json.loads(run("info", whitted, "--json", "--budget", "5", "--tolerance", "0.01"))["measured"]
assert loose["cheapest_within_tolerance"] == "whitted", loose["cheapest_within_tolerance"]
print(f"ok: whitted_1980 indirect diffuse {100 * share['value']:.2f} %, "
      f"whitted misses relMSE {techniques['whitted']['relmse_of_what_it_misses']['value']:.2g}")

text = run("info", whitted, "--budget", "5")
for pattern in [r"^present +direct-lighting, ", r"^measured +path, 128x96 px, \d+ spp",
                r"^  diffuse-interreflection +[0-9.]+ % \([0-9.]+-[0-9.]+\) +[0-9.e-]+ \(.*\) +(yes|no)$",
                r"^cheapest +path "]:
    assert re.search(pattern, text, re.M), f"no line matching {pattern!r} in:\n{text}"
print("ok: info's text")

for name, tolerance, expect_left in [("whitted_1980", "0.001", False), ("whitted_1980", "0.002", True),
                                     ("cornell_box", "0.001", False)]:
    stats_path = f"{out}/{name}_measured.json"
    text = run("render", f"{scenes}/{name}.json", "-t", "path", "-a", "bvh", "--width", "64", "--height", "48",
               "--spp", "4", "--set", "effects=measured", "--set", f"effects_tolerance={tolerance}",
               "--stats", stats_path, "-o", f"{out}/{name}_measured.png")
    skipped = json.load(open(stats_path))["skipped"]
    assert skipped["error_added_relmse_95"] <= skipped["tolerance_relmse"], skipped
    assert re.search(r"^effects=measured: left out .*; error added relMSE", text, re.M), text
    if expect_left:
        assert skipped["what"] != "" and not skipped["what"].startswith("nothing"), skipped
        assert "caustics" in skipped["what"], skipped
        assert "time_saved_fraction" in skipped and re.search(r"(% less time per sample|no measurable time saved)", text), (skipped, text)
    else:
        assert skipped["what"].startswith("nothing"), skipped
        assert "no time saved" in text, text
    print(f"ok: {name} effects=measured at {tolerance}: {skipped['what']}")

# Whitted and radiosity measure themselves: whitted's rays all show on its scene (nothing left out);
# radiosity stops shooting once the unshot light no longer shows, and says how many rows it did not compute.
text = run("render", f"{scenes}/whitted_1980.json", "-t", "whitted", "--width", "64", "--height", "48",
           "--set", "effects=measured", "--stats", f"{out}/whitted_w.json", "-o", f"{out}/whitted_w.png")
skipped = json.load(open(f"{out}/whitted_w.json"))["skipped"]
assert skipped["what"].startswith("nothing"), skipped
assert re.search(r"^effects=measured: left out nothing: .*; error added relMSE 0 \(tolerance 0.001\); no time saved",
                 text, re.M), text
print("ok: whitted effects=measured:", skipped["what"])
text = run("render", f"{scenes}/cornell_box.json", "-t", "radiosity", "--width", "64", "--height", "64",
           "--set", "effects=measured", "--set", "hemicube_res=16", "--stats", f"{out}/cornell_r.json",
           "-o", f"{out}/cornell_r.png")
skipped = json.load(open(f"{out}/cornell_r.json"))["skipped"]
assert 0 < skipped["error_added_relmse"] <= skipped["tolerance_relmse"], skipped
assert re.search(r"\d+ of \d+ hemicube rows computed", skipped["saved"]), skipped
assert re.search(r"^effects=measured: left out the shots of \d+ of \d+ patches.*hemicube rows computed", text, re.M), text
print("ok: radiosity effects=measured:", skipped["what"], "/", skipped["saved"])
