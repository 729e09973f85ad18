#!/usr/bin/env python3
"""Markdown tables for the lesson READMEs from bench_sweep's CSV files, so every number the
READMEs quote comes from a command anyone can re-run:

  build/bench/bench_sweep --lesson precision_near    # and precision_far, 06, 07
  bench/tables.py precision bench/results/precision_near.csv
  bench/tables.py precision bench/results/precision_far.csv
  bench/tables.py copy bench/results/06_dual_texture_8bit.csv bench/results/07_multidigit_16bit.csv
  bench/tables.py cost bench/results/shadow_cost.csv
  bench/tables.py pcf bench/results/pcf_cost.csv
  bench/tables.py front bench/results/05_pcf_dithered.csv   # any sweep's CSV: the table under its plot
  bench/tables.py bake bench/results/15_light_maps.csv       # lesson 15: error against what a bake costs
  bench/tables.py points docs/bench_16_choose_your_shadow.csv > 16_choose_your_shadow/bench_points.inc
"""
import csv
import statistics
import sys


def rows(path):
    with open(path, newline="") as f:
        return [r for r in csv.DictReader(f) if r.get("status") == "ok"]


def num(r, key):
    v = r.get(key, "")
    return float(v) if v not in ("", "nan") else None


def ordered(values):
    seen = []
    for v in values:
        if v not in seen:
            seen.append(v)
    return seen


def precision(path):
    data = rows(path)
    # The study's own axis: the third column (light_near, light_far, ...).
    with open(path, newline="") as f:
        axis = next(csv.reader(f))[2]
    held = {"light_near": "far 100", "light_far": "near 1"}.get(axis, "")
    values = ordered(r[axis] for r in data)
    maps = ordered(r["map"] for r in data)
    for scene in ordered(r["scene"] for r in data):
        print(f"\n{scene}: false shadow % / false lit % (1024² map, 640x480; {axis} across, "
              f"{held} held)\n")
        print(f"| map | " + " | ".join(values) + " |")
        print("|---|" + "---|" * len(values))
        for m in maps:
            cells = []
            for v in values:
                hit = [r for r in data if r["scene"] == scene and r["map"] == m and r[axis] == v]
                cells.append("—" if not hit else
                             f"{num(hit[0], 'false_shadow_pct'):.2f} / {num(hit[0], 'false_lit_pct'):.2f}")
            print(f"| {m} | " + " | ".join(cells) + " |")
    # What a frame costs, per map, over every point (the map is re-rendered each frame).
    print(f"\nframe cost in ms, medians over both scenes and every {axis} (map re-rendered "
          "each frame)\n")
    print("| map | frame | cpu | shadow pass | readback | eye (03-05) | pass 1 | pass 2 | pass 3 "
          "| frame / 8bit_projective |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    base = None
    for m in maps:
        hit = [r for r in data if r["map"] == m]

        def med(key):
            vals = [num(r, key) for r in hit if num(r, key) is not None]
            return f"{statistics.median(vals):.2f}" if vals else "—"
        frame = statistics.median(num(r, "frame_ms") for r in hit)
        base = base or frame
        print(f"| {m} | {frame:.1f} | {med('cpu_ms')} | {med('pass_ms.shadow')} | "
              f"{med('pass_ms.readback')} | {med('pass_ms.eye')} | {med('pass_ms.pass1')} | "
              f"{med('pass_ms.pass2')} | {med('pass_ms.pass3')} | {frame / base:.2f}× |")


def copy(paths):
    print("\nthe readback pass (ms, median), by map size, path and the light pass's depth bits\n")
    print("| lesson | path | depth bits | 256² | 512² | 1024² | 2048² | 512²/256² | 2048²/1024² "
          "| 24/16 bits at 1024² |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for path in paths:
        data = rows(path)
        for p in ordered(r["map.path"] for r in data):
            if p == "render_to_texture":
                continue  # no copy at all
            for bits in ("24", "16"):
                def ms(size, b=bits):
                    vals = [num(r, "pass_ms.readback") for r in data if r["map.path"] == p
                            and r["map.depth_bits"] == b and r["shadow.size"] == size]
                    vals = [v for v in vals if v is not None]
                    return statistics.median(vals) if vals else float("nan")
                sizes = [ms(s) for s in ("256", "512", "1024", "2048")]
                bits_ratio = ms("1024", "24") / ms("1024", "16")
                print(f"| {data[0]['lesson'][:2]} | {p} | {bits} | " +
                      " | ".join(f"{v:.2f}" for v in sizes) +
                      f" | {sizes[1] / sizes[0]:.1f}× | {sizes[3] / sizes[2]:.1f}× | {bits_ratio:.2f}× |")


def cost(path):
    """The shadow_cost study: each lesson's frame over its unshadowed baseline, same run."""
    data = rows(path)
    print("\nwhat a shadow costs: frame with shadows / the same frame with shadow.off (medians "
          "over the scenes; 1.00 = free)\n")
    print("| lesson | map cached: frame ms | baseline ms | ratio | map every frame: frame ms "
          "| ratio | map pass ms |")
    print("|---|---|---|---|---|---|---|")
    for lesson in ordered(r["lesson"] for r in data):
        def med(cache, off, key="frame_ms"):
            vals = [num(r, key) for r in data if r["lesson"] == lesson
                    and r["shadow.cache"] == cache and r["shadow.off"] == off]
            vals = [v for v in vals if v is not None]
            return statistics.median(vals) if vals else float("nan")
        base = med("true", "true")
        cached, fresh = med("true", "false"), med("false", "false")
        # The baseline renders no map, cached or not: both columns share it.
        base_fresh = med("false", "true")
        print(f"| {lesson} | {cached:.1f} | {base:.1f} | {cached / base:.2f}× | {fresh:.1f} | "
              f"{fresh / base_fresh:.2f}× | {med('false', 'false', 'pass_ms.shadow'):.1f} |")


def pcf(path):
    """The pcf_cost study: lesson 05's eye pass per kernel over the unshadowed eye pass."""
    data = rows(path)
    print("\nwhat PCF's taps cost: eye pass with the kernel / the same pass with shadow.off, "
          "per scene (median ms of the eye pass, CPU-time ratio in brackets)\n")
    scenes = ordered(r["scene"] for r in data)
    print("| kernel | " + " | ".join(f"{s}: eye ms | ratio" for s in scenes) + " |")
    print("|---|" + "---|---|" * len(scenes))
    for kernel in ordered(r["kernel"] for r in data):
        cells = []
        for scene in scenes:
            def pick(off, key):
                for r in data:
                    if r["kernel"] == kernel and r["scene"] == scene and r["shadow.off"] == off:
                        return num(r, key)
                return float("nan")
            eye, base = pick("false", "pass_ms.eye"), pick("true", "pass_ms.eye")
            cpu = pick("false", "cpu_ms") / pick("true", "cpu_ms")
            cells.append(f"{eye:.2f} | {eye / base:.2f}× ({cpu:.2f}×)")
        print(f"| {kernel} | " + " | ".join(cells) + " |")


# The plot's words for its error metrics (bench/plot.cpp), as column heads.
METRIC_HEADS = {
    "vis_mae": "vis_mae", "false_shadow_pct": "false shadow %", "false_lit_pct": "false lit %",
    "shade_mae": "shade_mae", "air_rel_rmse_pct": "air rel. RMSE %", "air_mae": "air_mae",
}
TIME_HEADS = {"cpu_ms": "CPU ms/frame", "frame_min_ms": "fastest frame ms",
              "frame_ms": "median frame ms"}


def metric_value(r, metric):
    if metric == "air_rel_rmse_pct":
        v = num(r, "air_rel_rmse")
        return None if v is None else 100 * v
    return num(r, metric)


def front(path):
    """The Pareto fronts bench_sweep marked in a sweep's CSV (on_front.<metric>, front_group;
    computed once, in bench/front.cpp): per group, every configuration on some metric's front,
    cheapest first, its error in bold where it is on that metric's front; and the lesson's
    default, on a front or not."""
    data = rows(path)
    metrics = [k[len("on_front."):] for k in (data[0].keys() if data else []) if k.startswith("on_front.")]
    if not metrics:
        sys.exit(f"{path}: no on_front columns (written by bench_sweep, or bench_sweep --replot)")
    time = data[0]["front_time"]
    for group in ordered(r["front_group"] for r in data if r["front_group"]):
        here = [r for r in data if r["front_group"] == group]
        shown = [r for r in here if r.get("is_default") == "1"
                 or any(r[f"on_front.{m}"] == "1" for m in metrics)]
        shown.sort(key=lambda r: (num(r, time), r["settings"]))
        print(f"\n{group}: the front, cheapest first (**bold**: on that error's front)\n")
        print(f"| setting | {TIME_HEADS.get(time, time)} | " +
              " | ".join(METRIC_HEADS.get(m, m) for m in metrics) + " |")
        print("|---|---|" + "---|" * len(metrics))
        for r in shown:
            cells = []
            for m in metrics:
                v = metric_value(r, m)
                text = "—" if v is None else f"{v:.3g}"
                cells.append(f"**{text}**" if r[f"on_front.{m}"] == "1" else text)
            name = r["settings"] + (" (default)" if r.get("is_default") == "1" else "")
            print(f"| {name} | {num(r, time):.3g} | " + " | ".join(cells) + " |")


def bake(path):
    """Lesson 15's sweep read against what the bake spends, not the frame (one lookup a pixel
    whatever was baked): per scene every configuration, fewest rays first, with its atlas and
    bytes; **bold** where no configuration with fewer rays has less error (the rays' front)."""
    data = rows(path)
    for scene in ordered(r["scene"] for r in data):
        here = sorted((r for r in data if r["scene"] == scene),
                      key=lambda r: (num(r, "lightmap/bake_rays"), num(r, "vis_mae")))
        print(f"\n{scene}: fewest rays first (**bold**: on the rays' front)\n")
        print("| setting | rays | bake s | atlas texels | bytes | vis_mae |")
        print("|---|---|---|---|---|---|")
        best = float("inf")
        for r in here:
            error = num(r, "vis_mae")
            on_front = error < best
            best = min(best, error)
            text = f"{error:.3g}"
            print(f"| {r['settings']} | {num(r, 'lightmap/bake_rays') / 1e6:.3g} M | "
                  f"{num(r, 'lightmap/bake_seconds'):.2g} | {int(num(r, 'lightmap/texels'))} | "
                  f"{num(r, 'lightmap/bytes') / 1e6:.2g} MB | " + (f"**{text}**" if on_front else text) + " |")


def points(path):
    """A sweep's points as C++ initializers, for a lesson's panel to draw the bench's front
    (lesson 16: bench_front.hpp): scene, light, setting, its settings, the front's time and
    vis_mae. The suite checks the lesson's copy is what this prints (bench_points_current)."""
    data = rows(path)
    time = data[0]["front_time"]
    def quote(text):
        return '"' + text.replace('\\', '\\\\').replace('"', '\\"') + '"'
    print(f"// Generated: bench/tables.py points {path}")
    print(f"inline constexpr const char* kBenchTime = {quote(time)};")
    print(f"inline constexpr const char* kBenchMachine = {quote(data[0]['machine'] + ', ' + data[0]['renderer'])};")
    sizes = ordered(f"{r['width']}x{r['height']}" for r in data)
    print(f"inline constexpr const char* kBenchSize = {quote(' '.join(sizes))};")
    print("inline constexpr BenchPoint kBenchPoints[] = {")
    for r in data:
        fields = ", ".join(quote(r[k]) for k in ("scene", "light", "setting", "settings"))
        print(f"    {{{fields}, {num(r, time):.6g}, {num(r, 'vis_mae'):.6g}}},")
    print("};")


if __name__ == "__main__":
    if len(sys.argv) >= 3 and sys.argv[1] == "precision":
        precision(sys.argv[2])
    elif len(sys.argv) >= 3 and sys.argv[1] == "cost":
        cost(sys.argv[2])
    elif len(sys.argv) >= 3 and sys.argv[1] == "pcf":
        pcf(sys.argv[2])
    elif len(sys.argv) >= 3 and sys.argv[1] == "front":
        front(sys.argv[2])
    elif len(sys.argv) >= 3 and sys.argv[1] == "bake":
        bake(sys.argv[2])
    elif len(sys.argv) >= 3 and sys.argv[1] == "points":
        points(sys.argv[2])
    elif len(sys.argv) >= 3 and sys.argv[1] == "copy":
        copy(sys.argv[2:])
    else:
        sys.exit(__doc__)
