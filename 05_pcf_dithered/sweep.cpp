// Lesson 05's time-vs-error sweep for bench_sweep (bench/README.md).
#include "lesson/sweep_spec.hpp"

// Kernels from cheapest to dearest, so the front shows where 001's 4-tap dither sits against 64
// taps. The radius in texels and the map size set the area light of the truth (a radius of 1 at
// 2048 is a radius of 2 at 1024): each truth gets its own front ("none" and hw2x2 have a hard
// truth and are left out); early_out=false shows what skipping settled neighbourhoods saves.
SHADOWS_SWEEP(
    {.scenes = {"torus_pyramid", "dueling"},
     .axes = {{"kernel",
               {"dithered4:pcf.mode=dithered", "grid4:pcf.mode=grid pcf.taps=4",
                "poisson16:pcf.mode=poisson pcf.taps=16", "grid16:pcf.mode=grid pcf.taps=16",
                "poisson64:pcf.mode=poisson pcf.taps=64", "grid64:pcf.mode=grid pcf.taps=64",
                "grid64_all_taps:pcf.mode=grid pcf.taps=64 pcf.early_out=false"}},
              {"pcf.radius", {"1", "2", "4"}},
              {"shadow.size", {"1024", "2048"}}},
     .fixed = {"shadow.cache=false", "inset=false", "pcf.count=false"},
     .plot_metrics = {"vis_mae", "false_lit_pct"}});
