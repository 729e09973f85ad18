#!/usr/bin/env python3
"""Contact hardening, measured: how wide the post's shadow is at each distance from its foot,
in the truth (a disk light), in PCSS and in lesson 05's single width.

Runs the lesson headless on the `contact` preset with a camera over the post's shadow, takes
each pixel's world position from the truth's job (--truth-job: the surfaces the lesson drew),
the truth's visibility from its trace (--truth-result) and the technique's from the visibility
view, and for every 0.25 units along the shadow measures its width across: the stretch where
the visibility, averaged in 0.01-unit strips, is under 0.95 (the umbra and both penumbrae).
A point light would give the post's own width, 0.16, all along.

  python3 14_soft_shadows/contact_plot.py [BUILD_DIR] [OUT_DIR]

writes OUT_DIR/contact.csv and OUT_DIR/contact.svg (defaults: build, 14_soft_shadows/pictures).
"""
import math
import os
import struct
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', 'tests'))
from png_read import read_png  # noqa: E402

# The contact preset (common/core/scene.cpp): the post's foot and the light.
POST = (-2.0, -1.3)
POST_HEIGHT = 2.2
LIGHT = (-4.5, 4.5, 2.2)
SIZE = (1280, 960)
CAMERA = ['--set', 'camera.pos=2.0,4.8,-0.6', '--set', 'camera.target=-1.0,0,-2.9']
MODES = [('truth', None), ('pcss', 'pcss'), ('fixed', 'fixed')]
STEP, STRIP, REACH = 0.25, 0.01, 0.6  # along the shadow, across it, how far to each side


def read_job(path):
    data = open(path, 'rb').read()
    magic, version = data[:4], struct.unpack_from('<I', data, 4)[0]
    assert magic == b'SHTJ' and version == 1, path
    off = 24  # magic, version, job id, scene id
    width, height, vertices, triangles = struct.unpack_from('<iiII', data, off)
    off += 16 + 8 + 12 + 12 + 4 + 4 + 4  # radius, offset; light: position, direction, flags
    # has air, then the air's block, written whether or not there is air: eye, inverse
    # view-projection, density, light position, light view-projection, samples, directional,
    # light direction, the spot's width and height (no spot here: 0 x 0 texels at the end).
    off += 4 + 12 + 64 + 4 + 12 + 64 + 4 + 4 + 12 + 8
    off += 4 * 3 * vertices + 4 * 3 * triangles
    n = width * height
    positions = struct.unpack_from('<%df' % (4 * n), data, off)
    return width, height, positions


def read_trace(path):
    data = open(path, 'rb').read()
    assert data[:4] == b'SHTR', path
    width, height = struct.unpack_from('<ii', data, 16)
    return struct.unpack_from('<%df' % (width * height), data, 16 + 8 + 8 + 8)


def run(build, sets, extra):
    cmd = [os.path.join(build, '14_soft_shadows'), '--headless', '--frames', '1', '--size',
           '%dx%d' % SIZE] + CAMERA + sets + extra
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)


def widths(positions, width, height, visibility):
    """The shadow's width at each step along it: {step index: width}."""
    axis = (POST[0] - LIGHT[0], POST[1] - LIGHT[2])
    length = math.hypot(*axis)
    u = (axis[0] / length, axis[1] / length)
    tip = POST_HEIGHT * length / (LIGHT[1] - POST_HEIGHT)
    strips = {}  # (step, strip) -> [sum, count]
    for i in range(width * height):
        x, y, z, obj = positions[4 * i:4 * i + 4]
        v = visibility(i)
        if obj < 0 or abs(y) > 1e-3 or v is None:  # counted pixels on the floor only
            continue
        dx, dz = x - POST[0], z - POST[1]
        along = dx * u[0] + dz * u[1]
        across = -dx * u[1] + dz * u[0]
        if along <= 0 or along >= tip - STEP or abs(across) >= REACH:
            continue
        key = (int(along / STEP), math.floor(across / STRIP))
        s = strips.setdefault(key, [0.0, 0])
        s[0] += v
        s[1] += 1
    out = {}
    for step in range(int((tip - STEP) / STEP)):
        row = [strips.get((step, k)) for k in range(-int(REACH / STRIP), int(REACH / STRIP))]
        seen = [r for r in row if r]
        if len(seen) < 0.8 * len(row):
            continue  # the camera does not see this stretch well enough
        out[step] = STRIP * sum(1 for r in seen if r[0] / r[1] < 0.95)
    return out


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else 'build'
    out_dir = sys.argv[2] if len(sys.argv) > 2 else os.path.join(HERE, 'pictures')
    tmp = tempfile.mkdtemp()
    job, trace = os.path.join(tmp, 'job'), os.path.join(tmp, 'trace')
    run(build, ['--set', 'pcss.mode=pcss'], ['--truth-job', job, '--truth-result', trace,
                                            '--out', os.path.join(tmp, 'x.png')])
    width, height, positions = read_job(job)
    truth = read_trace(trace)
    series = {'truth': widths(positions, width, height,
                              lambda i: truth[i] if truth[i] >= 0 else None)}
    for name, mode in MODES[1:]:
        png = os.path.join(tmp, name + '.png')
        run(build, ['--set', 'pcss.mode=' + mode, '--set', 'view=visibility', '--set',
                    'inset=false'], ['--no-truth', '--out', png])
        w, h, rows = read_png(png)
        # PNG rows top-down, the job's bottom-up.
        vis = lambda i, rows=rows: rows[h - 1 - i // w][4 * (i % w)] / 255.0
        series[name] = widths(positions, width, height,
                              lambda i: vis(i) if truth[i] >= 0 else None)
    steps = sorted(set(series['truth']) & set(series['pcss']) & set(series['fixed']))
    os.makedirs(out_dir, exist_ok=True)
    with open(os.path.join(out_dir, 'contact.csv'), 'w') as f:
        f.write('distance_from_foot,truth_width,pcss_width,fixed_width\n')
        for s in steps:
            f.write('%.3f,%.3f,%.3f,%.3f\n' % ((s + 0.5) * STEP, series['truth'][s],
                                               series['pcss'][s], series['fixed'][s]))
    write_svg(os.path.join(out_dir, 'contact.svg'), steps, series)
    for s in steps:
        print('%.2f  truth %.2f  pcss %.2f  fixed %.2f' % ((s + 0.5) * STEP, series['truth'][s],
                                                          series['pcss'][s], series['fixed'][s]))


def write_svg(path, steps, series):
    w, h, left, bottom = 520, 300, 50, 40
    xmax = (steps[-1] + 1) * STEP
    ymax = max(max(series[k][s] for s in steps) for k in series) * 1.15
    px = lambda d: left + (w - left - 20) * d / xmax
    py = lambda v: h - bottom - (h - bottom - 20) * v / ymax
    colours = {'truth': '#222222', 'pcss': '#d04020', 'fixed': '#2060c0'}
    labels = {'truth': 'truth (disk light, r = 0.3)', 'pcss': 'PCSS',
              'fixed': "lesson 05's single width"}
    parts = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" '
             'font-size="12"><rect width="100%%" height="100%%" fill="white"/>' % (w, h)]
    parts.append('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="black"/>' % (left, py(0), w - 20, py(0)))
    parts.append('<line x1="%d" y1="%d" x2="%d" y2="20" stroke="black"/>' % (left, py(0), left))
    for d in range(int(xmax) + 1):
        parts.append('<text x="%.1f" y="%d" text-anchor="middle">%d</text>' % (px(d), h - bottom + 16, d))
    tick = 0.1
    v = 0.0
    while v <= ymax:
        parts.append('<text x="%d" y="%.1f" text-anchor="end">%.1f</text>' % (left - 6, py(v) + 4, v))
        v += tick
    parts.append('<text x="%d" y="%d" text-anchor="middle">distance from the post\'s foot (world units)'
                 '</text>' % ((w + left) // 2, h - 6))
    parts.append('<text x="14" y="%d" transform="rotate(-90 14 %d)" text-anchor="middle">shadow width'
                 '</text>' % (h // 2, h // 2))
    for k, name in enumerate(['truth', 'pcss', 'fixed']):
        pts = ' '.join('%.1f,%.1f' % (px((s + 0.5) * STEP), py(series[name][s])) for s in steps)
        parts.append('<polyline fill="none" stroke="%s" stroke-width="2" points="%s"/>' %
                     (colours[name], pts))
        parts.append('<text x="%d" y="%d" fill="%s">%s</text>' % (left + 12, 36 + 16 * k,
                                                                 colours[name], labels[name]))
    parts.append('</svg>\n')
    open(path, 'w').write('\n'.join(parts))


if __name__ == '__main__':
    main()
