// Lesson 14's time-vs-error sweep for bench_sweep (bench/README.md).
#include "lesson/sweep_spec.hpp"

// The technique runs along each series, from a hard edge through lesson 05's single width to
// PCSS with more and more search taps; the filter's kernel picks the series. One truth, the
// disk light of the default radius, for every row: the front shows what the blocker search buys
// over a width that fits no edge, and where more search taps stop paying.
SHADOWS_SWEEP({.scenes = {"contact", "overlap"},
               .axes = {{"technique",
                         {"hard:pcss.mode=hard", "fixed:pcss.mode=fixed",
                          "pcss4:pcss.mode=pcss pcss.search_taps=4",
                          "pcss8:pcss.mode=pcss pcss.search_taps=8",
                          "pcss16:pcss.mode=pcss pcss.search_taps=16",
                          "pcss32:pcss.mode=pcss pcss.search_taps=32"}},
                        {"pcf.kernel", {"poisson", "grid"}},
                        {"pcf.taps", {"16", "32"}}},
               .fixed = {"inset=false", "pcss.count=false"},
               .plot_metrics = {"vis_mae", "false_lit_pct"}});
