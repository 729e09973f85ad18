// Lesson 10's sweep for bench_sweep (bench/README.md): error and under-sampling against the
// map's size, per projection, on each preset: which projection reaches a given error with the
// smallest map.
#include "lesson/sweep_spec.hpp"

SHADOWS_SWEEP({.scenes = {"dueling", "strategy", "receding"},
               .axes = {{"shadow.size", {"128", "256", "512", "1024", "2048"}},
                        {"light.projection", {"uniform", "focused", "lispsm", "plane_optimal"}}},
               // A square map: plane_optimal's guarantee needs the frame's aspect, but a sweep
               // of one size axis keeps every projection on the same texel budget.
               .fixed = {"shadow.cache=false", "inset=false"},
               .plot_metrics = {"false_lit_pct", "undersampled_pct"},
               .plot_along = true});
