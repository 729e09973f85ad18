// Lesson 09's time-vs-error sweep for bench_sweep (bench/README.md).
#include "lesson/sweep_spec.hpp"

// The method runs along each series: on torus_pyramid all three are right and z-fail pays for
// its caps; with the eye inside a volume z-pass is wrong at any price. The volume geometry and
// the stencil passes pick the series: per-triangle volumes cost their fill for nothing.
SHADOWS_SWEEP({.scenes = {"torus_pyramid", "eye_in_shadow"},
               .axes = {{"volume.method", {"zpass", "auto", "zfail"}},
                        {"volume.geometry", {"silhouette", "per_triangle"}},
                        {"stencil.mode", {"two_pass", "two_sided"}}},
               .fixed = {},
               .plot_metrics = {"false_shadow_pct", "false_lit_pct"}});
