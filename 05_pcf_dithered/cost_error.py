#!/usr/bin/env python3
"""Lesson 05's cost against error: every mode on every preset, one markdown table.

Usage: 05_pcf_dithered/cost_error.py BUILD_DIR [extra --set assignments...]
Each row: three headless runs (480x360, 10 timed frames each, the lesson's defaults otherwise:
1024² map, radius 2 texels, early out on); the eye pass time is the smallest of the three
medians, the least disturbed by whatever else the machine runs. Compare rows of one table,
not tables of different machines. Taps and errors are deterministic. The README quotes it.
"""
import json
import os
import subprocess
import sys
import tempfile

build, extra = sys.argv[1], sys.argv[2:]
modes = [("none", ["pcf.mode=none"]), ("hw2x2", ["pcf.mode=hw2x2"]),
         ("dithered 4", ["pcf.mode=dithered"]), ("poisson 16", ["pcf.mode=poisson", "pcf.taps=16"]),
         ("grid 16", ["pcf.mode=grid", "pcf.taps=16"]), ("grid 64", ["pcf.mode=grid", "pcf.taps=64"]),
         ("grid 64, no early out", ["pcf.mode=grid", "pcf.taps=64", "pcf.early_out=false"])]
print("| scene | mode | truth | taps/fragment | eye pass ms | vis_mae | false shadow % | false lit % |")
print("|---|---|---|---|---|---|---|---|")
with tempfile.TemporaryDirectory() as tmp:
    report = os.path.join(tmp, "r.json")
    for scene in ["torus_pyramid", "grazing", "dueling", "cubes"]:
        for name, sets in modes:
            sets = [f"scene={scene}"] + sets + extra
            if scene == "cubes":  # its own camera sees almost no lit caster
                sets += ["camera.pos=-4,5,7", "camera.target=0,0,0"]
            cmd = [f"{build}/05_pcf_dithered", "--headless", "--size", "480x360", "--frames", "10",
                   "--out", os.path.join(tmp, "o.png"), "--report", report]
            for s in sets:
                cmd += ["--set", s]
            eye = []
            for _ in range(3):
                subprocess.run(cmd, capture_output=True, check=True)
                r = json.load(open(report))
                eye.append(r["pass_ms"]["eye"])
            e = r["error"]
            print(f"| {scene} | {name} | {e['truth']} | {r['taps_per_filtered_fragment']:.2f} | "
                  f"{min(eye):.1f} | {e['vis_mae']:.5f} | {e['false_shadow_pct']:.3f} | "
                  f"{e['false_lit_pct']:.3f} |", flush=True)
