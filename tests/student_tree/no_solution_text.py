#!/usr/bin/env python3
"""The student tree holds no solution text.

Collects every solution region of the solution tree -- the solution branch of
`#if LIGHTLAB_SOLUTION` in the framework and assignment sources, every
`#if !LIGHTLAB_STUDENT_TREE` region (the framework's own answers to tasks), and
the answer files the student tree ships as object code only (marked
LIGHTLAB_ANSWER_FILE, which it must not hold at all) -- and fails when any file of
the student tree (sources, tests, data, docs, patches: every text file) holds
two or more consecutive non-trivial lines of one of them, naming the file and
line. Trivial lines are ignored: blank lines, braces and other punctuation,
comments, and lines of one word (`break;`, `else`, `default:`).

Usage: no_solution_text.py SOLUTION_ROOT STUDENT_TREE
"""
import os
import re
import sys

WORD = re.compile(r"[A-Za-z_][A-Za-z_0-9]*|[0-9][0-9.eEfF+-]*")
IDENT = re.compile(r"[A-Za-z_][A-Za-z_0-9]*")
# Words that say nothing about a solution on their own: `return true;` is as trivial as a brace.
KEYWORDS = {"return", "true", "false", "break", "continue", "else", "if", "for", "while", "do", "case", "default",
            "const", "auto", "nullptr", "void", "bool", "int", "float", "double", "static_cast", "std", "namespace"}


def normal(line):
    """The line without comments and spacing, or None if it is trivial."""
    line = re.sub(r"//.*$", "", line)
    line = re.sub(r"/\*.*?\*/", "", line)
    s = line.strip()
    if not s or s.startswith(("*", "/*", "#")):
        return None
    if len(WORD.findall(s)) < 2:
        return None
    if not [w for w in IDENT.findall(s) if w not in KEYWORDS]:
        return None
    return " ".join(s.split())


def solution_regions(path):
    """The solution regions of one C++ file: lists of (line number, text)."""
    regions, stack = [], []  # stack of [kind, lines] with kind True = inside a solution branch
    for number, line in enumerate(open(path, errors="replace"), 1):
        s = line.strip()
        if s.startswith("#if"):
            solution = bool(re.match(r"#if\s+LIGHTLAB_SOLUTION\b", s) or re.match(r"#if\s+!\s*LIGHTLAB_STUDENT_TREE\b", s))
            stack.append([solution, []])
            continue
        if s.startswith("#el") and stack:
            if stack[-1][0]:
                regions.append(stack[-1][1])
            stack[-1] = [False, []]
            continue
        if s.startswith("#endif") and stack:
            kind, lines = stack.pop()
            if kind:
                regions.append(lines)
            continue
        for frame in stack:
            if frame[0]:
                frame[1].append((number, line))
    return regions


def pairs(lines):
    """Consecutive non-trivial lines, as (first line number, (a, b))."""
    kept = [(n, normal(t)) for n, t in lines]
    kept = [(n, t) for n, t in kept if t]
    return [(kept[i][0], (kept[i][1], kept[i + 1][1])) for i in range(len(kept) - 1)]


def answer_files(root):
    """Every file of the solution tree marked LIGHTLAB_ANSWER_FILE: shipped as object code only."""
    files = []
    for base in ("framework", "assignments"):
        for d, _, names in os.walk(os.path.join(root, base)):
            for name in names:
                path = os.path.join(d, name)
                if name.endswith((".cpp", ".h")) and "LIGHTLAB_ANSWER_FILE" in open(path, errors="replace").read(4096):
                    files.append(os.path.relpath(path, root))
    return files


def main():
    root, tree = sys.argv[1], sys.argv[2]
    known = {}  # pair -> where in the solution
    for base in ("framework", "assignments"):
        for d, _, names in os.walk(os.path.join(root, base)):
            for name in names:
                if not name.endswith((".cpp", ".h")):
                    continue
                path = os.path.join(d, name)
                for region in solution_regions(path):
                    for n, p in pairs(region):
                        known.setdefault(p, f"{os.path.relpath(path, root)}:{n}")
    answers = answer_files(root)
    present = [rel for rel in answers if os.path.exists(os.path.join(tree, rel))]
    if present:
        sys.exit("FAIL: the student tree holds answer files (object code only): " + ", ".join(present))
    for rel in answers:
        path = os.path.join(root, rel)
        lines = list(enumerate(open(path, errors="replace"), 1))
        for n, p in pairs(lines):
            known.setdefault(p, f"{rel}:{n}")
    if len(known) < 200:
        sys.exit(f"FAIL: only {len(known)} solution line pairs found in {root}: is it the solution tree?")
    leaks, scanned = [], 0
    for d, dirs, names in os.walk(tree):
        rel_dir = os.path.relpath(d, tree)
        dirs[:] = [x for x in dirs if not (rel_dir == "." and (x.startswith("build") or x in (".git", "out")))]
        for name in names:
            path = os.path.join(d, name)
            try:
                data = open(path, "rb").read()
            except OSError:
                continue
            if b"\0" in data[:65536]:
                continue  # object code: the references, images
            scanned += 1
            text = data.decode("utf-8", errors="replace").splitlines(keepends=True)
            for n, p in pairs(list(enumerate(text, 1))):
                if p in known:
                    leaks.append(f"{os.path.relpath(path, tree)}:{n}: solution text (from {known[p]}): {p[0]} / {p[1]}")
    if leaks:
        print(f"FAIL: the student tree holds solution text ({len(leaks)} places):")
        print("\n".join("  " + l for l in leaks[:60]))
        sys.exit(1)
    print(f"no solution text: {scanned} text files of {tree} checked against {len(known)} pairs of solution lines")


if __name__ == "__main__":
    main()
