#!/usr/bin/env python3
"""Grades a class's submissions in one command: every file in a folder, across the machine's
cores, by the lessons' own grader (--grade, the truth's measure), into one CSV and a summary.

A submission is what a student hands in: the file the panel's "Save settings" writes (its
"# grade it: LESSON --grade N" line names the lesson and the exercise), or a page's link saved
as text (https://.../04_bias_offset.html?exercise=1&bias.mode=gradient). The student is the
file's name without its extension, or its folder's for a file one level down
(submissions/ada/04.txt is ada's). A file that is not a submission (prose, binary, too large,
a setting the exercise does not allow) is a row with its reason, never a stop.

  scripts/grade_class.py SUBMISSIONS_DIR [--out grades.csv] [--jobs N]
                         [--lesson 04_bias_offset --exercise 1]   (for files that name neither)

Exit 0 when every submission was graded (met or not), 1 when some were not met, 2 when some
could not be graded. BUILD_DIR (default build) holds the lessons.
"""
import argparse
import csv
import json
import os
import re
import subprocess
import sys
import tempfile
import urllib.parse
from concurrent.futures import ThreadPoolExecutor

BUILD = os.environ.get("BUILD_DIR", os.path.join(os.path.dirname(__file__), "..", "build"))
MOST_BYTES = 64 * 1024  # a settings file is a few hundred bytes
PAGE_ONLY = {"exercise", "size", "hide-panel", "no-truth", "panel"}  # a page's, not a setting
LESSON = re.compile(r"[0-9]{2}_[a-z0-9_]+")


def submissions(folder):
    """(student, path) for every file in the folder and one level down, sorted."""
    found = []
    for entry in sorted(os.scandir(folder), key=lambda e: e.name):
        if entry.name.startswith("."):
            continue
        if entry.is_dir(follow_symlinks=False):
            for inner in sorted(os.scandir(entry.path), key=lambda e: e.name):
                if not inner.name.startswith(".") and not inner.is_dir(follow_symlinks=False):
                    found.append((entry.name, inner.path))
        else:
            found.append((os.path.splitext(entry.name)[0], entry.path))
    return found


def read(path):
    """The submission's text, or raises ValueError with the reason it is not one."""
    try:
        with open(path, "rb") as f:
            data = f.read(MOST_BYTES + 1)
    except OSError as e:
        raise ValueError(f"cannot read it ({e.strerror})") from e
    if len(data) > MOST_BYTES:
        raise ValueError(f"over {MOST_BYTES // 1024} KB: not a settings file or a link")
    if b"\0" in data:
        raise ValueError("binary: not a settings file or a link")
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as e:
        raise ValueError("not UTF-8 text") from e


def understand(text, lesson, exercise):
    """(lesson, exercise, settings lines) from a settings file or a page's link."""
    link = re.search(r"(?:^|/)([0-9]{2}_[a-z0-9_]+)\.html\?(\S*)", text, re.M)
    if link:
        lesson = link.group(1)
        lines = []
        for key, value in urllib.parse.parse_qsl(link.group(2), keep_blank_values=True):
            if key == "exercise":
                exercise = value
            elif key not in PAGE_ONLY:
                lines.append(f"{key}={value}")
        settings = "\n".join(lines) + "\n"
    else:
        said = re.search(r"^#\s*grade it:\s*(\S+)\s+--grade\s+(\S+)", text, re.M)
        if said:
            lesson, exercise = os.path.basename(said.group(1)), said.group(2)
        settings = text
    if not lesson or not exercise:
        raise ValueError("names no lesson and exercise (a saved settings file has a "
                         "'# grade it:' line; or give --lesson and --exercise)")
    if not LESSON.fullmatch(lesson) or not os.path.isfile(os.path.join(BUILD, lesson)):
        raise ValueError(f"no lesson {lesson!r} in {BUILD}")
    if not re.fullmatch(r"[0-9]{1,3}", exercise):
        raise ValueError(f"exercise {exercise!r} is not a number")
    return lesson, int(exercise), settings


def grade(job):
    student, path, lesson, exercise = job
    row = {"student": student, "file": path, "lesson": "", "exercise": "", "verdict": "",
           "figures": {}, "error": ""}
    try:
        lesson, exercise, settings = understand(read(path), lesson, exercise)
    except ValueError as e:
        row.update(verdict="BAD", error=str(e))
        return row
    row.update(lesson=lesson, exercise=exercise)
    with tempfile.TemporaryDirectory(prefix="grade_") as tmp:
        given = os.path.join(tmp, "settings.txt")
        with open(given, "w", encoding="utf-8") as f:
            f.write(settings)
        report = os.path.join(tmp, "report.json")
        try:
            run = subprocess.run([os.path.join(BUILD, lesson), "--grade", str(exercise),
                                  "--settings", given, "--report", report],
                                 capture_output=True, text=True, errors="replace", timeout=600)
        except subprocess.TimeoutExpired:
            row.update(verdict="BAD", error="the grade took over 10 minutes")
            return row
        said = (run.stderr.strip() or run.stdout.strip()).splitlines()
        if run.returncode not in (0, 1):
            # The grader's own reason, with the file's name in place of the copy graded.
            reason = said[-1] if said else f"exit {run.returncode}"
            row.update(verdict="BAD", error=reason.replace(given, os.path.basename(path)))
            return row
        try:
            with open(report, encoding="utf-8") as f:
                verdict = json.load(f)["exercise"]
        except (OSError, ValueError, KeyError) as e:
            row.update(verdict="BAD", error=f"no verdict in the report ({e})")
            return row
    row["verdict"] = "MET" if run.returncode == 0 else "NOT MET"
    row["figures"] = verdict.get("measured", {})
    return row


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("folder")
    parser.add_argument("--out", default="grades.csv")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    parser.add_argument("--lesson", default="")
    parser.add_argument("--exercise", default="")
    args = parser.parse_args()
    if not os.path.isdir(args.folder):
        print(f"grade_class: no folder {args.folder}", file=sys.stderr)
        return 2
    jobs = [(s, p, args.lesson, args.exercise) for s, p in submissions(args.folder)]
    rows = []
    with ThreadPoolExecutor(max(1, args.jobs)) as pool:
        for row in pool.map(grade, jobs):
            rows.append(row)
            print(f"grade_class: {len(rows)}/{len(jobs)} {row['student']}: {row['verdict']}",
                  file=sys.stderr)
    figures = sorted({name for r in rows for name in r["figures"]})
    with open(args.out, "w", newline="", encoding="utf-8") as f:
        out = csv.writer(f)
        out.writerow(["student", "file", "lesson", "exercise", "verdict", *figures, "error"])
        for r in rows:
            out.writerow([r["student"], r["file"], r["lesson"], r["exercise"], r["verdict"],
                          *[r["figures"].get(name, "") for name in figures], r["error"]])
    count = {v: sum(r["verdict"] == v for r in rows) for v in ("MET", "NOT MET", "BAD")}
    print(f"grade_class: {len(rows)} submissions: {count['MET']} met, {count['NOT MET']} not "
          f"met, {count['BAD']} not graded; {args.out}")
    return 2 if count["BAD"] else 1 if count["NOT MET"] else 0


if __name__ == "__main__":
    sys.exit(main())
