#!/usr/bin/env python3
"""Lesson 04's defaults against lights nobody tuned for: random light positions on every preset.

Usage: 04_bias_offset/random_lights.py BUILD_DIR [SEED] [COUNT] [MODE,MODE,...]
Prints each configuration and, per bias mode, the worst false shadow / false lit seen
(shadow.size 2048, 320x240, the lesson's other defaults). The README quotes its output.
"""
import math
import random
import re
import subprocess
import sys

build = sys.argv[1]
random.seed(int(sys.argv[2]) if len(sys.argv) > 2 else 11)
count = int(sys.argv[3]) if len(sys.argv) > 3 else 60
modes = (sys.argv[4] if len(sys.argv) > 4 else "back_faces,polygon_offset,gradient,normal_offset").split(",")
worst = {m: [0.0, 0.0, ""] for m in modes}
for _ in range(count):
    scene = random.choice(["torus_pyramid", "grazing", "dueling", "cubes"])
    y, r, a = random.uniform(0.8, 10), random.uniform(3, 10), random.uniform(0, 2 * math.pi)
    pos = f"{r * math.cos(a):.2f},{y:.2f},{r * math.sin(a):.2f}"
    kind = random.choice(["spot", "spot", "directional"])
    row = f"{scene:13s} {kind:11s} {pos:18s}"
    for mode in modes:
        sets = [f"scene={scene}", "shadow.size=2048", f"light.pos={pos}", f"light.type={kind}",
                f"bias.mode={mode}"]
        if scene == "cubes":  # its own camera sees almost no lit caster
            sets += ["camera.pos=-4,5,7", "camera.target=0,0,0"]
        cmd = [f"{build}/04_bias_offset", "--headless", "--size", "320x240", "--frames", "1",
               "--out", "/dev/null"]
        for s in sets:
            cmd += ["--set", s]
        line = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout
        # "false shadow 0.09%  false lit 0.24%" (the line also says "... without shadow").
        shadow = float(re.search(r"false shadow\s+([0-9.]+)%", line).group(1))
        lit = float(re.search(r"false lit\s+([0-9.]+)%", line).group(1))
        row += f"  {mode} {shadow:.2f}/{lit:.2f}"
        if shadow > worst[mode][0]:
            worst[mode][0], worst[mode][2] = shadow, f"{scene} {kind} light.pos={pos}"
        worst[mode][1] = max(worst[mode][1], lit)
    print(row, flush=True)
for mode, (shadow, lit, where) in worst.items():
    print(f"worst {mode}: false shadow {shadow:.2f}% ({where}), false lit {lit:.2f}%")
