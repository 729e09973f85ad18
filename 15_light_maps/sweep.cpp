// Lesson 15's time-vs-error sweep for bench_sweep (bench/README.md).
#include "lesson/sweep_spec.hpp"

// The bake's two knobs, texels a unit and samples a texel, against the truth. A frame is one
// lookup whatever the bake cost, so the frame times sit together: what moves is what the bake
// spent. Its rays, texels and seconds are columns of their own (run with SHADOWS_CACHE=off to
// time every bake: a cached one reports 0 s), the front to read against them.
SHADOWS_SWEEP({.scenes = {"torus_pyramid", "contact"},
               .axes = {{"lightmap.texels_per_unit", {"4", "8", "16", "32"}},
                        {"lightmap.samples", {"1", "4", "16", "64"}}},
               .fixed = {"inset=false", "shadow.cache=false"},
               .plot_metrics = {"vis_mae"},
               .report_numbers = {"lightmap/bake_rays", "lightmap/texels", "lightmap/bytes",
                                  "lightmap/bake_seconds"}});
