// Lesson 16's sweep for bench_sweep (bench/README.md): every technique at a few of its own
// settings (in the order of the lesson's choice, so the plot's colours are the panel's), on
// each preset, under a point light, a disk of radius 0.1, and the disk with the last caster
// moved 1.2 along x after the light map's bake: one front across techniques a preset and a
// light, each technique's own front in its colour beneath it.
// Maps are rendered every frame (the cost of a scene where something always moves); what a
// technique cannot do with a preset's light (cascades under a lamp, a cube under the sun) the
// lesson refuses, and the sweep leaves out.
#include "lesson/sweep_spec.hpp"

SHADOWS_SWEEP(
    {.scenes = {"contact", "street", "bulb", "yard", "torus_pyramid"},
     .axes = {{"setting",
               {"hard_1024:technique=hard hard/shadow.size=1024",
                "hard_2048:technique=hard hard/shadow.size=2048",
                "hard_4096:technique=hard hard/shadow.size=4096",
                "pcf_dithered_1024:technique=pcf pcf/shadow.size=1024",
                "pcf_dithered_2048:technique=pcf pcf/shadow.size=2048",
                "pcf_poisson16_2048:technique=pcf pcf/shadow.size=2048 pcf/pcf.mode=poisson "
                "pcf/pcf.taps=16",
                "pcf_grid64_1024:technique=pcf pcf/shadow.size=1024 pcf/pcf.mode=grid "
                "pcf/pcf.taps=64",
                "vsm_1024:technique=filtered filtered/shadow.size=1024 filtered/filter.method=vsm",
                "esm_1024:technique=filtered filtered/shadow.size=1024 filtered/filter.method=esm",
                "msm_1024:technique=filtered filtered/shadow.size=1024 filtered/filter.method=msm",
                "pcss_1024:technique=pcss pcss/shadow.size=1024",
                "pcss_2048:technique=pcss pcss/shadow.size=2048",
                "cascades_1:technique=cascades cascades/cascades.count=1",
                "cascades_2:technique=cascades cascades/cascades.count=2",
                "cascades_4:technique=cascades cascades/cascades.count=4",
                "cascades_4_2048:technique=cascades cascades/cascades.count=4 "
                "cascades/cascades.size=2048",
                "cube_256:technique=cube cube/cube.size=256",
                "cube_512:technique=cube cube/cube.size=512",
                "cube_1024:technique=cube cube/cube.size=1024",
                "tetrahedron_512:technique=cube cube/omni.method=tetrahedron cube/cube.size=512",
                "paraboloids_512:technique=cube cube/omni.method=paraboloid cube/cube.size=512",
                "lightmap_16:technique=lightmap",
                "lightmap_32:technique=lightmap lightmap/lightmap.texels_per_unit=32",
                "lightmap_hybrid:technique=lightmap lightmap/lightmap.mode=hybrid",
                "volumes:technique=volumes",
                "plane_optimal_frame:technique=warped warped/shadow.size=640 "
                "warped/shadow.height=480",
                "plane_optimal_1024:technique=warped warped/shadow.size=1024",
                "lispsm_1024:technique=warped warped/light.projection=lispsm "
                "warped/shadow.size=1024"}},
              {"light",
               {"point:light.radius=0", "disk:light.radius=0.1",
                "disk_moved:light.radius=0.1 move.x=1.2"}}},
     .fixed = {"shadow.cache=false"},
     .plot_metrics = {"vis_mae"},
     .series = "technique"});
