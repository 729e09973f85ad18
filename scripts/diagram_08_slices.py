#!/usr/bin/env python3
"""Lesson 08's diagram (issue 19): slices crossing an eye ray, seen from the side.

Writes docs/diagram_08_slices.png with gnuplot. The eye looks along +x; each slice is a plane
of constant view depth (a vertical line here), at uFar - (i + 0.5) * uStep as slice.vert
places it. Where the eye ray crosses a slice, slice.frag adds density x spot x shadow x the
length of ray the slice stands for; the dots say what that sample sees. The geometry is made
up, the rule is the shader's.
Usage: scripts/diagram_08_slices.py [outdir]   (default docs)
"""
import math
import subprocess
import sys

out = sys.argv[1] if len(sys.argv) > 1 else "docs"

LIGHT = (6.0, 6.0)
HALF_ANGLE = math.radians(25.0)  # the spot's cone around straight down
CASTER, RADIUS = (6.6, 2.6), 0.55
EYE = (0.0, 1.6)
RAY_END = (11.0, 0.5)  # the eye ray ends on the back wall at x = 11
NEAR, FAR, SLICES = 1.0, 11.0, 10
STEP = (FAR - NEAR) / SLICES


def ray_at(x):
    t = (x - EYE[0]) / (RAY_END[0] - EYE[0])
    return (x, EYE[1] + t * (RAY_END[1] - EYE[1]))


def in_cone(p):
    dx, dy = p[0] - LIGHT[0], p[1] - LIGHT[1]
    return dy < 0 and abs(math.atan2(dx, -dy)) <= HALF_ANGLE


def in_shadow(p):
    # Does the segment from the point to the light pass through the caster (a disk)?
    px, py = p
    lx, ly = LIGHT
    cx, cy = CASTER
    dx, dy = lx - px, ly - py
    t = max(0.0, min(1.0, ((cx - px) * dx + (cy - py) * dy) / (dx * dx + dy * dy)))
    return math.hypot(px + t * dx - cx, py + t * dy - cy) < RADIUS


def wedge():
    # The caster's shadow inside the cone: the two tangents from the light, down to y = 0.
    vx, vy = CASTER[0] - LIGHT[0], CASTER[1] - LIGHT[1]
    a = math.asin(RADIUS / math.hypot(vx, vy))
    pts = []
    for s in (-a, a):
        dx = vx * math.cos(s) - vy * math.sin(s)
        dy = vx * math.sin(s) + vy * math.cos(s)
        t = -LIGHT[1] / dy
        pts.append((LIGHT[0] + t * dx, 0.0))
    return pts


g = [
    'set terminal pngcairo size 980,560 font ",11" noenhanced',
    f'set output "{out}/diagram_08_slices.png"',
    'set title "Lesson 08: slices crossing one eye ray (side view; the eye looks to the right)"',
    "unset border; unset tics; unset key",
    "set xrange [-0.6:12.4]; set yrange [-0.9:6.8]",
    "set size ratio -1",
]
obj = 1


def polygon(points, colour, extra=""):
    global obj
    coords = " to ".join(f"{x:.3f},{y:.3f}" for x, y in points + [points[0]])
    g.append(f'set object {obj} polygon from {coords} fc rgb "{colour}" '
             f"fs solid 1.0 noborder {extra}")
    obj += 1


# The lit cone down to the floor, the caster's shadow in it, the floor and the back wall.
spread = LIGHT[1] * math.tan(HALF_ANGLE)
polygon([LIGHT, (LIGHT[0] + spread, 0.0), (LIGHT[0] - spread, 0.0)], "#fff2b0", "back")
w = wedge()
polygon([CASTER, w[0], w[1]], "#c8c8c8", "back")
g.append(f'set object {obj} circle at {CASTER[0]},{CASTER[1]} size {RADIUS} '
         'fc rgb "#6a7fa8" fs solid 1.0 front')
obj += 1
g.append('set arrow from -0.5,0 to 11,0 nohead lw 2 lc rgb "#555555" back')
g.append('set arrow from 11,0 to 11,6.5 nohead lw 2 lc rgb "#555555" back')
g.append(f'set label "light" at {LIGHT[0] - 0.25},{LIGHT[1] + 0.1} right')
g.append(f'set label "caster" at {CASTER[0] + 0.7},{CASTER[1] + 0.3} left')
g.append('set label "its shadow in the air" at 8.3,2.4 left font ",10"')
g.append('set arrow from 8.25,2.35 to 7.1,1.6 head size 0.15,20 lc rgb "#555555" front')
g.append(f'set label "eye" at {EYE[0]},{EYE[1] + 0.35} center')

# The slices: planes of constant view depth, numbered back to front as they are drawn.
for i in range(SLICES):
    x = FAR - (i + 0.5) * STEP
    g.append(f'set arrow from {x:.3f},-0.2 to {x:.3f},6.4 nohead dt 2 lc rgb "#8080c0" back')
    g.append(f'set label "{i}" at {x:.3f},6.55 center font ",9" tc rgb "#6060a0"')
g.append(f'set label "slice i at depth uFar - (i + 0.5) * uStep (drawn back to front, i = 0 '
         f'first)" at 6,-0.55 center font ",10" tc rgb "#6060a0"')
# One interval of uStep, where the jitter may move that slice's sample.
x1 = FAR - 1.5 * STEP
g.append(f'set arrow from {x1 - STEP / 2:.3f},5.3 to {x1 + STEP / 2:.3f},5.3 heads size 0.1,90 '
         'lc rgb "#6060a0"')
g.append(f'set label "uStep: the jitter moves\\na pixel\'s sample\\nwithin it" at {x1:.3f},4.9 '
         'center font ",10" tc rgb "#6060a0"')
g.append(f'set label "eye ray" at 2.2,1.15 center font ",10"')

# The eye ray and the sample where it crosses each slice.
g.append(f'set arrow from {EYE[0]},{EYE[1]} to {RAY_END[0]},{RAY_END[1]} head filled lw 2 '
         'lc rgb "#202020" front')
data = {"lit": [], "shadowed": [], "dark": []}
for i in range(SLICES):
    p = ray_at(FAR - (i + 0.5) * STEP)
    kind = "dark" if not in_cone(p) else "shadowed" if in_shadow(p) else "lit"
    data[kind].append(p)
g.append('set label "filled: in the cone and sees the light, adds density x spot x uStep x |ray|'
         '" at 0,-0.15 left font ",10" offset 0,-2.6')
g.append('set label "open: in the cone\'s shadow (shadowTest = 0) or outside the cone (spot = 0)'
         ': adds 0" at 0,-0.15 left font ",10" offset 0,-3.6')
g.append("set bmargin 4")
plots = []
styles = {"lit": 'pt 7 ps 1.8 lc rgb "#e0a000"', "shadowed": 'pt 6 ps 1.8 lc rgb "#404040"',
          "dark": 'pt 6 ps 1.2 lc rgb "#909090"'}
for kind, points in data.items():
    if points:
        plots.append(("'-' with points " + styles[kind], points))
g.append("plot " + ", ".join(p for p, _ in plots) if plots else "plot NaN")
for _, points in plots:
    g.extend(f"{x:.3f} {y:.3f}" for x, y in points)
    g.append("e")

subprocess.run(["gnuplot"], input="\n".join(g) + "\n", text=True, check=True)
