#!/usr/bin/env python3
"""scripts/grade_class.py on a class of its own (issue 55, 3): saved settings files and a page's
link, right and wrong, beside files that are no submission (prose, binary, too large, a setting
the exercise does not allow, a name with a comma and quotes). Every file is a row; the bad ones
give their reason; the right ones are MET with the figures the grader alone gives; the same
settings as a file and as a link grade the same; the exit code and the summary count them.
  python3 tests/grade_class_test.py BUILD_DIR
"""
import csv
import os
import subprocess
import sys
import tempfile

build = os.path.abspath(sys.argv[1])
root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
failures = []


def expect(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL " + what)


def settings(exercise, *lines):
    # What the panel's Save settings writes (ExerciseRun::save).
    return (f"# 04_bias_offset settings: 04_bias_offset --settings x.txt\n"
            f"# exercise {exercise}: Acne and peter panning, both, where the light grazes\n"
            f"# grade it: 04_bias_offset --grade {exercise} --settings x.txt\n" +
            "".join(line + "\n" for line in lines))


with tempfile.TemporaryDirectory() as tmp:
    class_dir = os.path.join(tmp, "submissions")
    os.makedirs(os.path.join(class_dir, "hal"))
    files = {
        "ada.txt": settings(1, "bias.mode=gradient", "bias.factor=1.1", "bias.units=4",
                            "bias.clamp=0.25"),
        "bob.txt": settings(1, "bias.mode=back_faces"),
        "cy.txt": "https://example.edu/course/shadows/04_bias_offset.html?exercise=1&bias.mode=gradient\n",
        "dee.txt": "I moved the bias until it looked right.\n",
        "gus.txt": settings(1, "shadow.size=4096"),
        'name, with "quotes".txt': settings(1, "bias.mode=gradient"),
        "hal/attempt.txt": settings(1, "bias.mode=gradient"),
    }
    for name, text in files.items():
        with open(os.path.join(class_dir, name), "w", encoding="utf-8") as f:
            f.write(text)
    with open(os.path.join(class_dir, "eve.txt"), "wb") as f:
        f.write(b"\x7fELF\0\0\0binary")
    with open(os.path.join(class_dir, "fay.txt"), "w", encoding="utf-8") as f:
        f.write("bias.mode=gradient\n" * 10000)

    out = os.path.join(tmp, "grades.csv")
    run = subprocess.run([sys.executable, os.path.join(root, "scripts/grade_class.py"), class_dir,
                          "--out", out, "--jobs", "2"], capture_output=True, text=True,
                         env={**os.environ, "BUILD_DIR": build})
    print(run.stdout, end="")
    expect(run.returncode == 2, f"exit {run.returncode}, not 2 (some not graded)")
    expect("9 submissions: 4 met, 1 not met, 4 not graded" in run.stdout,
           f"summary: {run.stdout.strip()}")
    with open(out, newline="", encoding="utf-8") as f:
        rows = {r["student"]: r for r in csv.DictReader(f)}
    expect(len(rows) == 9, f"{len(rows)} rows, not 9: {sorted(rows)}")
    verdicts = {s: r["verdict"] for s, r in rows.items()}
    for student, verdict in [("ada", "MET"), ("bob", "NOT MET"), ("cy", "MET"), ("hal", "MET"),
                             ('name, with "quotes"', "MET"), ("dee", "BAD"), ("eve", "BAD"),
                             ("fay", "BAD"), ("gus", "BAD")]:
        expect(verdicts.get(student) == verdict, f"{student}: {verdicts.get(student)}, not {verdict}")
    reasons = {s: r["error"] for s, r in rows.items()}
    for student, says in [("dee", "names no lesson and exercise"), ("eve", "binary"),
                          ("fay", "over 64 KB"), ("gus", "not shadow.size")]:
        expect(says in reasons.get(student, ""), f"{student}'s reason: {reasons.get(student)!r}")
    # The figures are the grader's own, and the same settings as a file and as a link agree.
    ada, cy = rows.get("ada", {}), rows.get("cy", {})
    shadow = ada.get("/error/false_shadow_pct", "")
    expect(shadow != "" and float(shadow) <= 0.07, f"ada's false shadow: {shadow!r}")
    expect(shadow == cy.get("/error/false_shadow_pct") and
           ada.get("/error/false_lit_pct") == cy.get("/error/false_lit_pct"),
           "the same settings as a file and as a link graded differently")
    expect(rows.get("bob", {}).get("lesson") == "04_bias_offset", "bob's lesson")

print("grade_class: ok" if not failures else f"grade_class: {len(failures)} failures")
sys.exit(1 if failures else 0)
