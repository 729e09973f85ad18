// Lesson 13's time-vs-error sweep for bench_sweep (bench/README.md).
#include "lesson/sweep_spec.hpp"

// PCF's N x N taps a pixel every frame against a filterable map's 2N-tap blur once per map and
// one lookup a pixel, at the same widths (each width its own matched area light, so its own
// front). The map is re-rendered every frame (shadow.cache=false), so the blur is paid every
// frame too: the sweep compares the filters' cost, not the cache's.
SHADOWS_SWEEP({.scenes = {"stacked", "torus_pyramid"},
               .axes = {{"filter.method", {"pcf", "vsm", "esm"}},
                        {"filter.taps", {"3", "5", "8"}},
                        {"filter.radius", {"2", "4"}}},
               .fixed = {"shadow.cache=false", "inset=false"},
               .plot_metrics = {"vis_mae", "false_lit_pct"}});
