// Lesson 08's time-vs-error sweep for bench_sweep (bench/README.md).
#include "sweep_spec.hpp"

// Slices against the air's error: where more slices stop paying (the map's resolution or the
// truth's own noise), with and without jitter, on two map sizes.
SHADOWS_SWEEP({.scenes = {"room"},
               .axes = {{"air.slices", {"4", "8", "16", "32", "48", "64", "96", "128"}},
                        {"air.jitter", {"false", "true"}},
                        {"shadow.size", {"256", "1024"}}},
               .fixed = {"shadow.cache=false", "inset=false"},
               .plot_metrics = {"air_rel_rmse_pct", "air_mae"}});
