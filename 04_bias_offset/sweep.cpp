// Lesson 04's time-vs-error sweep for bench_sweep (bench/README.md).
#include "lesson/sweep_spec.hpp"

// Bias costs nothing: the plot is about error, along the constant bias from none to far too
// much (acne falls, then peter panning rises), one series per method.
SHADOWS_SWEEP({.scenes = {"torus_pyramid", "grazing"},
               .axes = {{"bias.units", {"0", "1", "4", "64", "1000", "10000", "100000", "1000000"}},
                        {"bias.mode",
                         {"constant_only", "polygon_offset", "clip_translate", "back_faces",
                          "normal_offset"}},
                        {"bias.factor", {"1.1", "2"}}},
               .fixed = {"shadow.size=2048", "shadow.cache=false", "inset=false"},
               .plot_metrics = {"false_shadow_pct", "false_lit_pct"},
               .plot_along = true});
