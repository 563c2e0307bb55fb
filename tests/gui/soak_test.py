#!/usr/bin/env python3
"""A classroom's abuse of the GUI, replayed from a fixed seed under Xvfb.

  soak_test.py LIGHTLAB OUT_DIR [--seconds 60] [--seed 1] [--big-scene SCENE]

1. The GUI opens a copy of the Cornell box. For SECONDS a seeded random
   session clicks, drags, scrolls and presses keys anywhere in the window
   (never Ctrl+Q), while the scene file it watches is overwritten with bad
   files: Latin-1 text, binary bytes, a valid scene followed by NUL bytes, a
   2 GB (sparse) file, then deleted, then restored.
2. Every 5 s a heartbeat: F12 must give a screenshot and its sidecar within
   5 s (else the GUI hangs), and the resident memory is sampled.
3. It fails on a crash (the GUI gone), a hang, or memory that keeps growing
   (the last sample above twice the first one after the warm-up, plus 300 MB).
4. Ctrl+Q ends the process within 3 s (exit status 0).
5. With --big-scene (the 235k-triangle Cornell bunny): a pane starts radiosity,
   and Ctrl+Q during its work still ends the process within 3 s.

A longer soak is the same command with --seconds 300 (README, "Soak test").
"""
import argparse
import glob
import json
import os
import random
import shutil
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
W, H = 1280, 800


def xdo(*args):
    subprocess.run(["xdotool", *map(str, args)], check=False, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def rss_mb(pid):
    with open(f"/proc/{pid}/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024.0
    return 0.0


class Gui:
    def __init__(self, lightlab, args, log):
        self.log = open(log, "w")
        self.proc = subprocess.Popen([lightlab, "gui", "--window", str(W), "--window-height", str(H), *args],
                                     stdout=self.log, stderr=subprocess.STDOUT)
        subprocess.run(["xdotool", "search", "--sync", "--name", "LightLab"], check=True, stdout=subprocess.DEVNULL)

    def alive(self):
        return self.proc.poll() is None

    def kill(self):
        if self.alive():
            self.proc.kill()
            self.proc.wait()


def fail(message, gui=None, log=None):
    print("FAIL: " + message)
    if gui is not None and not gui.alive() and log:
        print(open(log, errors="replace").read()[-4000:])
    if gui is not None:
        gui.kill()
    sys.exit(1)


def heartbeat(gui, log, n):
    """F12; the screenshot's sidecar must appear within 5 s."""
    for f in glob.glob("lightlab_*"):
        os.remove(f)
    xdo("key", "F12")
    start = time.monotonic()
    while time.monotonic() - start < 5.0:
        if not gui.alive():
            fail(f"the GUI died (exit {gui.proc.returncode}) before heartbeat {n}", gui, log)
        for name in glob.glob("lightlab_*.json"):
            try:
                json.load(open(name))
                return time.monotonic() - start
            except (ValueError, OSError):
                pass  # still being written
        time.sleep(0.05)
    fail(f"heartbeat {n}: no frame for 5 s after F12 (the GUI hangs)", gui, log)


def random_action(rng):
    x, y = rng.randrange(W), rng.randrange(H)
    kind = rng.choices(["click", "drag", "wheel", "key", "hold"], [4, 3, 3, 3, 1])[0]
    if kind == "click":
        xdo("mousemove", x, y, "click", rng.choice([1, 1, 1, 3]))
    elif kind == "drag":
        button = rng.choice([1, 3, 2])
        xdo("mousemove", x, y, "mousedown", button)
        for _ in range(rng.randrange(2, 6)):
            x = min(max(x + rng.randrange(-200, 200), 0), W - 1)
            y = min(max(y + rng.randrange(-200, 200), 0), H - 1)
            xdo("mousemove", x, y)
        xdo("mouseup", button)
    elif kind == "wheel":
        xdo("mousemove", x, y, "click", "--repeat", rng.randrange(1, 40), "--delay", 1, rng.choice([4, 5]))
    elif kind == "key":
        keys = ["w", "a", "s", "d", "q", "e", "p", "i", "h", "r", "1", "2", "4", "Left", "Right", "Up", "Down",
                "Tab", "Return", "Escape", "space", "BackSpace", "Delete", "Next", "Prior", "F11", "x", "z", "9"]
        xdo("key", rng.choice(keys))
    else:
        k = rng.choice("wasdqe")
        xdo("keydown", k)
        time.sleep(rng.uniform(0.1, 0.8))
        xdo("keyup", k)
    time.sleep(rng.uniform(0.0, 0.05))


def bad_files(scene, good):
    """What the watched scene file becomes, in turn, during the session."""
    text = open(good, encoding="utf-8").read()
    latin1 = text.replace("{", '{\n"description": "Gr\u00fc\u00dfe f\u00fcr die Vorlesung",', 1)

    def write(data):
        with open(scene, "wb") as f:
            f.write(data)

    def sparse():
        with open(scene, "wb") as f:
            f.write(b"{")
            f.truncate(2 << 30)

    def delete():
        os.remove(scene)

    return [("latin-1 text", lambda: write(latin1.encode("latin-1"))),
            ("binary bytes", lambda: write(bytes(range(256)) * 64)),
            ("valid scene + NUL bytes", lambda: write(text.encode() + b"\0" * 65536)),
            ("a 2 GB file", sparse),
            ("deleted", delete),
            ("restored", lambda: write(text.encode()))]


def quit_within(gui, seconds, what):
    xdo("key", "ctrl+q")
    start = time.monotonic()
    try:
        code = gui.proc.wait(timeout=seconds)
    except subprocess.TimeoutExpired:
        fail(f"{what}: Ctrl+Q did not end the process within {seconds} s", gui)
    took = time.monotonic() - start
    if code != 0:
        fail(f"{what}: exit status {code} after Ctrl+Q")
    print(f"ok: {what}: Ctrl+Q ended the process in {took:.2f} s")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("lightlab")
    p.add_argument("out")
    p.add_argument("--seconds", type=float, default=60.0)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--big-scene")
    a = p.parse_args()
    lightlab = os.path.abspath(a.lightlab)
    shutil.rmtree(a.out, ignore_errors=True)
    os.makedirs(a.out)
    os.chdir(a.out)
    good = os.path.join(ROOT, "data/scenes/cornell_box.json")
    scene = os.path.abspath("watched_scene.json")
    shutil.copy(good, scene)

    rng = random.Random(a.seed)
    log = os.path.abspath("gui.log")
    gui = Gui(lightlab, ["--ui-scale", "2", scene], log)
    files = bad_files(scene, good)
    start = time.monotonic()
    next_beat, next_file, beats, samples, actions = start + 5.0, start + 8.0, 0, [], 0
    while time.monotonic() - start < a.seconds:
        if not gui.alive():
            fail(f"the GUI died (exit {gui.proc.returncode}) after {actions} random actions", gui, log)
        now = time.monotonic()
        if now >= next_file and files:
            name, change = files.pop(0)
            change()
            print(f"{now - start:5.1f} s: the scene file is now: {name}")
            next_file = now + 8.0
        if now >= next_beat:
            beats += 1
            latency = heartbeat(gui, log, beats)
            samples.append(rss_mb(gui.proc.pid))
            print(f"{now - start:5.1f} s: heartbeat {beats} in {latency:.2f} s, {samples[-1]:.0f} MB resident, "
                  f"{actions} actions")
            next_beat = time.monotonic() + 5.0
        random_action(rng)
        actions += 1
    for name, change in files:
        change()  # a short session: still make every file change, and leave the good scene in place
    if not gui.alive():
        fail(f"the GUI died (exit {gui.proc.returncode})", gui, log)
    heartbeat(gui, log, beats + 1)
    samples.append(rss_mb(gui.proc.pid))
    base = samples[min(2, len(samples) - 1)]
    print(f"memory: {base:.0f} MB after the warm-up, {samples[-1]:.0f} MB at the end, {max(samples):.0f} MB at most")
    if samples[-1] > 2.0 * base + 300.0:
        fail(f"memory grew from {base:.0f} MB to {samples[-1]:.0f} MB", gui, log)
    print(f"ok: {actions} random actions over {a.seconds:.0f} s (seed {a.seed}), {len(samples)} heartbeats, no crash, "
          "no hang")
    quit_within(gui, 3.0, "after the session")

    if a.big_scene:
        preset = os.path.abspath("radiosity_big.json")
        json.dump({"lightlab_preset": 1, "scene": os.path.abspath(a.big_scene), "width": 160, "height": 160,
                   "panes": [{"technique": "radiosity", "accelerator": "bvh", "spp": 1}]}, open(preset, "w"))
        gui = Gui(lightlab, ["--preset", preset], log)
        time.sleep(8.0)  # the scene loads, the radiosity pane starts its long work
        if not gui.alive():
            fail("the GUI died on the big scene", gui, log)
        print(f"big scene: {rss_mb(gui.proc.pid):.0f} MB resident before Ctrl+Q")
        quit_within(gui, 3.0, "during radiosity on the big scene")


if __name__ == "__main__":
    main()
