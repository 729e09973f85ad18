// Lesson 07's time-vs-error sweep for bench_sweep (bench/README.md): seed 000's copy paths,
// the same sweep as lesson 06's (common/lesson/sweep_spec.hpp).
#include "lesson/sweep_spec.hpp"

SHADOWS_SWEEP(::shadows::copyCostSweep());
