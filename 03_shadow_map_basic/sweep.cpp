// Lesson 03's time-vs-error sweep for bench_sweep (bench/README.md).
#include "lesson/sweep_spec.hpp"

SHADOWS_SWEEP({.scenes = {"torus_pyramid", "cubes"},
               .axes = {{"shadow.size", {"128", "256", "512", "1024", "2048", "4096"}},
                        {"shadow.format", {"16", "24", "32f"}},
                        {"shadow.filter", {"nearest", "linear"}}},
               // No cache: a static frame would otherwise skip the shadow pass and not pay for
               // it. No inset: the corner depth view is a teaching aid, not part of the
               // technique.
               .fixed = {"shadow.cache=false", "inset=false"},
               // Split by failure mode: with no bias, acne (false shadow) does not depend on the
               // map at all, while aliasing at shadow edges (false lit) falls with its size.
               .plot_metrics = {"false_shadow_pct", "false_lit_pct"}});
