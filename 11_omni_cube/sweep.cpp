// Lesson 11's time-vs-error sweep for bench_sweep (bench/README.md).
#include "lesson/sweep_spec.hpp"

// The cube rendered every frame (its cost is the six passes), along the face size, in both
// stores and both filters: what each texel a side buys in error, and what the linear write of
// the distance store costs against each face's own hardware depth.
SHADOWS_SWEEP({.scenes = {"bulb", "dueling"},
               .axes = {{"cube.size", {"64", "128", "256", "512", "1024"}},
                        {"cube.store", {"distance", "depth"}},
                        {"cube.filter", {"nearest", "linear"}}},
               .fixed = {"shadow.cache=false"},
               .plot_metrics = {"false_shadow_pct", "false_lit_pct"}});
