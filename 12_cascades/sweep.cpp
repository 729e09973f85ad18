// Lesson 12's time-vs-error sweep for bench_sweep (bench/README.md).
#include "lesson/sweep_spec.hpp"

// The maps rendered every frame (their cost is one pass a cascade), along the cascade count,
// in both fits, snapped and not: what each cascade buys in error, what the sphere's looser
// box costs in it, and the shimmer each leaves (the report's shimmer_pct, a column and a plot).
SHADOWS_SWEEP({.scenes = {"street", "street_low_sun"},
               .axes = {{"cascades.count", {"1", "2", "3", "4"}},
                        {"cascades.fit", {"slice", "sphere"}},
                        {"cascades.snap", {"false", "true"}}},
               .fixed = {"shadow.cache=false"},
               .plot_metrics = {"false_shadow_pct", "false_lit_pct", "shimmer_pct"},
               .report_numbers = {"shimmer_pct"}});
