#!/usr/bin/env python3
"""Looks for shortcuts in the exercises: every slider an exercise allows, moved alone from the
exercise's starting point to each end of its range and five points between (each choice, each
bool), graded by the truth. A move that meets a goal should be the lesson's idea, not a slider
that measures less (instructor/SOLUTIONS.md, "No shortcut").

Usage: scripts/exercise_shortcuts.py [lesson-prefix ...]   (BUILD_DIR, default build)
Prints each move that meets its goal, then how many moves were graded. Takes a few minutes.
"""
import os
import re
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

BUILD = os.environ.get("BUILD_DIR", "build")


def lessons(prefixes):
    names = sorted(d for d in os.listdir(BUILD) if re.fullmatch(r"\d\d_[a-z0-9_]+", d)
                   and not d.endswith(("_gl41", "_gles30")))
    return [n for n in names if not prefixes or any(n.startswith(p) for p in prefixes)]


def values(kind, default, help_text):
    """The values a slider is moved to: the other choices, the other bool, or seven points
    spread over a number's range (and five more spread by ratio where the range is positive)."""
    if kind == "choice":
        found = re.search(r"one of (.*)$", help_text)
        options = [v.strip() for v in found.group(1).split(",")] if found else []
    elif kind == "bool":
        options = ["true", "false"]
    elif kind in ("int", "float"):
        found = re.search(r"in \[([-0-9.e+]+), ([-0-9.e+]+)\]", help_text)
        if not found:
            return []
        lo, hi = float(found.group(1)), float(found.group(2))
        points = [lo + (hi - lo) * k / 6 for k in range(7)]
        if lo > 0:
            points += [lo * (hi / lo) ** (k / 6) for k in range(1, 6)]
        options = sorted({str(round(x)) if kind == "int" else f"{x:.4g}" for x in points})
    else:
        return []
    return [v for v in options if v != default]


def params(lesson):
    listed = subprocess.run([f"{BUILD}/{lesson}", "--list-params"], capture_output=True,
                            text=True, check=True).stdout
    found = {}
    for line in listed.splitlines():
        m = re.match(r"(\S+)\s+(\w+)\s+default (\S+)\s+(.*)", line)
        if m:
            found[m.group(1)] = values(m.group(2), m.group(3), m.group(4))
    return found


def moves(lesson):
    """(lesson, exercise, parameter, value) for every allowed slider of every exercise."""
    sliders = params(lesson)
    found = []
    for n in range(1, 10):
        # The grader names what an exercise allows when refusing what it does not.
        said = subprocess.run([f"{BUILD}/{lesson}", "--grade", str(n), "--set", "no.such=1"],
                              capture_output=True, text=True)
        allowed = re.search(r"lets you set (.*); not", said.stdout + said.stderr)
        if not allowed:
            break
        names = re.split(r", | and ", allowed.group(1).split(" (")[0])
        for name in names:
            if name in sliders and name != "view":
                found += [(lesson, n, name, v) for v in sliders[name]]
    return found


def grade(move):
    lesson, n, name, value = move
    run = subprocess.run([f"{BUILD}/{lesson}", "--grade", str(n), "--set", f"{name}={value}"],
                         capture_output=True, text=True)
    lines = run.stdout.strip().splitlines()
    return move, run.returncode, lines[-1] if lines else ""


def main():
    all_moves = [m for lesson in lessons(sys.argv[1:]) for m in moves(lesson)]
    print(f"exercise_shortcuts: {len(all_moves)} moves to grade", file=sys.stderr)
    met = 0
    with ThreadPoolExecutor(os.cpu_count() or 2) as pool:
        for done, (move, code, verdict) in enumerate(pool.map(grade, all_moves), 1):
            if done % 20 == 0:
                print(f"exercise_shortcuts: {done}/{len(all_moves)}", file=sys.stderr)
            if code == 0:
                met += 1
                lesson, n, name, value = move
                print(f"{lesson} exercise {n}: {name}={value} meets it: {verdict}")
            elif code != 1:
                print(f"{move}: exit {code}: {verdict}", file=sys.stderr)
    print(f"{met} of {len(all_moves)} single moves meet their exercise's goal")


if __name__ == "__main__":
    main()
