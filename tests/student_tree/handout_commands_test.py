#!/usr/bin/env python3
"""Every shell command of every handout runs, word for word, in the student tree.

Takes each line of the ```sh blocks of assignments/*/README.md (and of the
student workflow section of README.md), runs it with bash from the tree's root,
and fails on a non-zero exit, or when its picture carries the stripes of another
assignment's stubs (an A4 command striped by A2's stubs: the handout should add
`--reference A2`; the tree is fresh, so every stub is still there). A command that runs GoogleTest must run at least
one test (in a fresh student tree the task tests fail -- the stubs -- so there
the exit status of a test command is not judged, only that it ran tests and
did not crash). A `gui` command runs under Xvfb and takes one screenshot.

Usage: handout_commands_test.py STUDENT_TREE WORKDIR
"""
import os
import re
import shlex
import subprocess
import sys
import time


def commands(markdown):
    out, block = [], False
    lines = open(markdown).read().splitlines()
    i = 0
    while i < len(lines):
        line = lines[i]
        if line.strip().startswith("```"):
            block = line.strip() in ("```sh", "```bash") if not block else False
            i += 1
            continue
        if block and line.strip() and not line.strip().startswith("#"):
            text = line
            while text.rstrip().endswith("\\") and i + 1 < len(lines):
                i += 1
                text = text.rstrip()[:-1] + " " + lines[i].strip()
            out.append((i + 1, text.strip()))
        i += 1
    return out


def main():
    tree, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    handouts = sorted(os.path.join(tree, "assignments", d, "README.md") for d in os.listdir(os.path.join(tree, "assignments"))
                      if os.path.exists(os.path.join(tree, "assignments", d, "README.md")) and re.match(r"a\d_", d))
    if len(handouts) < 6:
        sys.exit(f"FAIL: {len(handouts)} handouts in {tree}")
    failures, ran = [], 0
    for handout in handouts:
        rel = os.path.relpath(handout, tree)
        assignment = "A" + re.match(r"a(\d)_", os.path.basename(os.path.dirname(handout))).group(1)
        for line, command in commands(handout):
            words = shlex.split(command, comments=True)
            if not words:
                continue
            shown = f"{rel}:{line}: {command}"
            run = command
            if len(words) > 1 and "gui" in words[1:3]:
                shot = os.path.join(work, f"gui_{ran}.png")
                run = ("xvfb-run -a -n 180 -s '-noreset -screen 0 1280x800x24' " + " ".join(shlex.quote(w) for w in words) +
                       f" --screenshot {shlex.quote(shot)} --frames 2 --timeout 300")
            start = time.time()
            try:
                p = subprocess.run(["bash", "-c", run], cwd=tree, capture_output=True, text=True, timeout=900,
                                   errors="replace")
            except subprocess.TimeoutExpired:
                failures.append(f"{shown}\n    did not finish in 900 s")
                continue
            ran += 1
            out = p.stdout + p.stderr
            is_test = "gtest" in command or any(w.endswith(("lightlab_task_tests", "lightlab_tests")) for w in words)
            if is_test:
                counts = [int(n) for n in re.findall(r"\[==========\] (\d+) tests? from", out)]
                if not counts or max(counts) == 0:
                    failures.append(f"{shown}\n    runs no test:\n      " + "\n      ".join(out.strip().splitlines()[-5:]))
                elif p.returncode not in (0, 1):
                    failures.append(f"{shown}\n    crashed (exit {p.returncode}):\n      " +
                                    "\n      ".join(out.strip().splitlines()[-8:]))
                else:
                    print(f"ok ({time.time() - start:.0f} s, {max(counts)} tests): {shown}")
                continue
            # "lightlab: A2.1 not implemented: ... -- its reference stood in; those pixels are striped magenta"
            foreign = sorted({m for m in re.findall(r"(A\d)\.\d+ not implemented: .*striped", out) if m != assignment})
            if p.returncode != 0:
                failures.append(f"{shown}\n    exit {p.returncode}:\n      " + "\n      ".join(out.strip().splitlines()[-8:]))
            elif foreign:
                failures.append(f"{shown}\n    its picture is striped by the stubs of " + ", ".join(foreign) +
                                " (add --reference " + ",".join(foreign) + " before the subcommand)")
            else:
                print(f"ok ({time.time() - start:.0f} s): {shown}")
    if failures:
        print(f"FAIL: {len(failures)} handout commands do not run as written:")
        print("\n".join("  " + f for f in failures))
        sys.exit(1)
    print(f"every handout command runs: {ran} commands in {len(handouts)} handouts")


if __name__ == "__main__":
    main()
