// Lesson 08's time-vs-error sweep for bench_sweep (bench/README.md).
#include "lesson/sweep_spec.hpp"

// Slices against the air's resolution: where more slices stop paying, and what computing the
// air at 1/2, 1/3 or 1/4 of the width and height (upsampled by depth) costs in error.
SHADOWS_SWEEP({.scenes = {"room"},
               .axes = {{"air.slices", {"16", "24", "32", "48", "64", "96", "128"}},
                        {"air.downsample", {"1", "2", "3", "4"}}},
               .fixed = {"shadow.cache=false", "inset=false"},
               .plot_metrics = {"air_rel_rmse_pct", "air_mae"}});
