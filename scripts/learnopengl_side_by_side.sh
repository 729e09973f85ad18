#!/usr/bin/env bash
# A lesson against the LearnOpenGL chapter that teaches the same technique, on the same work,
# on this machine's llvmpipe: instructions per frame and per pass (callgrind, deterministic), per
# map texel and per shaded pixel, and (05 only) frame times over interleaved rounds. It fetches
# nothing: give it a LearnOpenGL checkout.
#
#   scripts/learnopengl_side_by_side.sh [LEARNOPENGL_DIR] [--chapter C] [--frames N] [--rounds R]
#
# --chapter pcf (the default): 5.advanced_lighting/3.1.3 shadow mapping, its 3x3 PCF, against
#   lesson 05: its cubes, 800x600, a 3x3 grid over adjacent texels, every tap, the map rendered
#   every frame, with each pcf.lookup; its best setting at the same error (the early out, the
#   map cached), one lookup a pixel (pcf.mode=none, for scale) and shadow.off (no lookup).
# --chapter point: 3.2.1 point shadows (a 1024 cube of distances, six faces by a geometry
#   shader, near 1, far 25, one tap, bias 0.05) against lesson 11 with the same cube, store,
#   planes, tap and bias, every face every frame (cube.skip=false), and with its skipping on.
# --chapter csm: 8.guest/2021/2.csm (cascades fitted to slices, no snapping, no blend, the
#   maps every frame) against lesson 12 set the same way; what cannot be matched is printed.
# The chapter is built from the checkout as it is, against the system's GLFW and GLM, with a
# small harness applied to a copy of its main loop (shaders and draw calls untouched; csm's
# window 800x600 instead of 2560x1440): N frames then exit, no vsync, and the frame, its depth
# pass and its lit pass each bracketed by glFinish, their times on stderr, and after the last
# frame the pixels its depth buffer covers. Needs valgrind, xvfb-run, g++ and a build
# (cmake --build build --target 05_pcf_dithered 11_omni_cube 12_cascades).
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
logl="" frames=6 rounds=5 chapter_name=pcf
while [[ $# -gt 0 ]]; do
  case $1 in
    --frames) frames=$2; shift 2 ;;
    --rounds) rounds=$2; shift 2 ;;
    --chapter) chapter_name=$2; shift 2 ;;
    -h|--help) sed -n 2,25p "${BASH_SOURCE[0]}"; exit 0 ;;
    -*) echo "learnopengl_side_by_side: unknown option $1 (--chapter C, --frames N, --rounds R)" >&2; exit 2 ;;
    *) logl=$1; shift ;;
  esac
done
[[ $frames =~ ^[0-9]+$ && $frames -ge 4 ]] || { echo "learnopengl_side_by_side: --frames must be 4 or more" >&2; exit 2; }
[[ $rounds =~ ^[0-9]+$ && $rounds -ge 1 ]] || { echo "learnopengl_side_by_side: --rounds must be 1 or more" >&2; exit 2; }
if [[ -z $logl ]]; then
  cat <<'EOF'
learnopengl_side_by_side: no LearnOpenGL checkout given, nothing measured.
  git clone https://github.com/JoeyDeVries/LearnOpenGL /tmp/LearnOpenGL
  scripts/learnopengl_side_by_side.sh /tmp/LearnOpenGL [--chapter pcf|point|csm]
(measured at its commit a545a70; docs/MEASUREMENTS.md has the tables)
EOF
  exit 0
fi
[[ -d $logl ]] || { echo "learnopengl_side_by_side: $logl is not a folder" >&2; exit 2; }
logl=$(cd "$logl" && pwd)  # its programs run from their chapter's folder
[[ $logl != *[\"\\]* ]] || { echo "learnopengl_side_by_side: a path with quotes or backslashes" >&2; exit 2; }
# Per chapter: its folder, its program, the lesson, and where its depth pass ends (the line
# after the pass's glBindFramebuffer(GL_FRAMEBUFFER, 0)).
case $chapter_name in
  pcf) chapter=$logl/src/5.advanced_lighting/3.1.3.shadow_mapping source=shadow_mapping.cpp
       ours=05_pcf_dithered depth_end='// reset viewport' ;;
  point) chapter=$logl/src/5.advanced_lighting/3.2.1.point_shadows source=point_shadows.cpp
         ours=11_omni_cube depth_end='// 2. render scene as normal' ;;
  csm) chapter=$logl/src/8.guest/2021/2.csm source=shadow_mapping.cpp
       ours=12_cascades depth_end='// reset viewport' ;;
  *) echo "learnopengl_side_by_side: --chapter is pcf, point or csm, not '$chapter_name'" >&2; exit 2 ;;
esac
[[ -f $chapter/$source ]] || { echo "learnopengl_side_by_side: $chapter/$source not found" >&2; exit 2; }
lesson=$repo/build/$ours
[[ -x $lesson ]] || { echo "learnopengl_side_by_side: $lesson not built" >&2; exit 2; }
for tool in valgrind xvfb-run g++ python3; do
  command -v $tool >/dev/null || { echo "learnopengl_side_by_side: needs $tool" >&2; exit 2; }
done

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# The harness, on a copy: its model.h (assimp) is not used by this chapter.
python3 - "$chapter/$source" "$work/main.cpp" "$frames" "$depth_end" <<'PY'
import sys
src, out, frames, depth_end = open(sys.argv[1]).read(), sys.argv[2], sys.argv[3], sys.argv[4]
def once(old, new):
    global src
    assert src.count(old) == 1, old
    src = src.replace(old, new)
once('#include <learnopengl/model.h>\n', '#include <chrono>\n#include <cstdio>\n#include <vector>\n')
# csm draws at 2560x1440: the same 800x600 as the others and the lessons.
if 'SCR_WIDTH = 2560' in src:
    once('SCR_WIDTH = 2560', 'SCR_WIDTH = 800')
    once('SCR_HEIGHT = 1440', 'SCR_HEIGHT = 600')
# Every glFinish of the harness is this function's: callgrind dumps after it, so the depth
# pass and the lit pass each land in a dump of their own.
once('// settings\n', 'extern "C" __attribute__((noinline)) void harness_finish() { glFinish(); }\n\n// settings\n')
once('glfwMakeContextCurrent(window);', 'glfwMakeContextCurrent(window);\n    glfwSwapInterval(0);')
once('while (!glfwWindowShouldClose(window))',
     'for (int harness_frame = 0; harness_frame < %s && !glfwWindowShouldClose(window); ++harness_frame)' % frames)
once('        processInput(window);\n',
     '        processInput(window);\n        harness_finish();\n'
     '        const auto harness_t0 = std::chrono::steady_clock::now();\n')
# The depth pass ends where the chapter binds the window's framebuffer again.
once('        glBindFramebuffer(GL_FRAMEBUFFER, 0);\n\n        ' + depth_end,
     '        glBindFramebuffer(GL_FRAMEBUFFER, 0);\n        harness_finish();\n'
     '        const auto harness_t1 = std::chrono::steady_clock::now();\n\n        ' + depth_end)
once('        glfwSwapBuffers(window);',
     '        harness_finish();\n        const auto harness_t2 = std::chrono::steady_clock::now();\n'
     '        const auto harness_ms = [](auto a, auto b) { return std::chrono::duration<double, std::milli>(b - a).count(); };\n'
     '        std::fprintf(stderr, "harness frame_ms %.4f depth_ms %.4f lit_ms %.4f\\n", harness_ms(harness_t0, harness_t2),\n'
     '                     harness_ms(harness_t0, harness_t1), harness_ms(harness_t1, harness_t2));\n'
     '        glfwSwapBuffers(window);')
# After the last frame (after its swap: in no frame's dumps), the pixels the scene covers: the
# window's depth buffer short of the far plane.
end = src.rindex('    glfwTerminate();')
src = src[:end] + (
    '    {\n        std::vector<float> harness_depth(SCR_WIDTH * SCR_HEIGHT);\n'
    '        glReadPixels(0, 0, SCR_WIDTH, SCR_HEIGHT, GL_DEPTH_COMPONENT, GL_FLOAT, harness_depth.data());\n'
    '        size_t harness_covered = 0;\n'
    '        for (float d : harness_depth) harness_covered += d < 1.0f ? 1 : 0;\n'
    '        std::fprintf(stderr, "harness shaded_pixels %zu\\n", harness_covered);\n    }\n') + src[end:]
open(out, 'w').write(src)
PY
echo "const char * logl_root = \"$logl\";" > "$work/root_directory.h"
g++ -O2 -std=c++17 -I"$work" -I"$logl/includes" "$work/main.cpp" "$logl/src/glad.c" \
  "$logl/src/stb_image.cpp" -lglfw -ldl -lpthread -o "$work/logl" 2>"$work/build.log" ||
  { cat "$work/build.log" >&2; exit 1; }
export LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe
# The median of sorted numbers, one a line: the middle one, or the mean of the middle two (as
# the lessons' frame_ms is).
median() { awk '{a[NR] = $1} END { if (NR % 2) print a[(NR + 1) / 2]; else print (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }
logl_run() { (cd "$chapter" && xvfb-run -a -s "-screen 0 1024x768x24" "$@"); }

# Instructions: a dump before each glfwSwapBuffers and after each harness_finish (llvmpipe
# rasterizes a pass in the glFinish that ends it), so that a frame (from one swap to the next;
# the swap itself is a few thousand instructions: llvmpipe's picture is presented by X) is four
# dumps: what ran up to the frame's first glFinish (its input, and the swap's events), the depth
# pass (with the window's first clear), the lit pass, and the timing line. The first start-up
# too; the medians of the frames after the first two.
LP_NUM_THREADS=0 logl_run valgrind --tool=callgrind --dump-before=glfwSwapBuffers \
  --dump-after=harness_finish --callgrind-out-file="$work/cg.out" "$work/logl" \
  >/dev/null 2>"$work/valgrind.log" || { tail "$work/valgrind.log" >&2; exit 1; }
read -r logl_ir logl_depth logl_lit logl_rest < <(python3 - "$work" <<'PY'
import glob, re, statistics, sys
dumps = []
for f in glob.glob(sys.argv[1] + '/cg.out.*'):
    text = open(f).read()
    trigger = re.search(r'^desc: Trigger: --dump-(?:before|after)=(\S+)', text, re.M)
    if trigger:
        dumps.append((int(f.rsplit('.', 1)[1]), trigger.group(1),
                      int(re.search(r'^summary: (\d+)', text, re.M).group(1))))
frames, segments = [], []
for _, trigger, ir in sorted(dumps):
    segments.append(ir)
    if trigger == 'glfwSwapBuffers':
        frames.append(segments)
        segments = []
steady = [f for f in frames[2:] if len(f) == 4]
if not steady or len(steady) != len(frames) - 2:
    sys.exit(f'learnopengl_side_by_side: {len(steady)} of {len(frames) - 2} frames after the first two '
           'were dumped in four parts (--frames must be 4 or more)')
m = lambda xs: statistics.median(xs)
print(m([sum(f) for f in steady]), m([f[1] for f in steady]), m([f[2] for f in steady]),
      m([f[0] + f[3] for f in steady]))
PY
)
logl_pixels=$(sed -nE 's/^harness shaded_pixels ([0-9]+)$/\1/p' "$work/valgrind.log" | tail -1)
M() { python3 -c "print(f'{$1 / 1e6:.2f}')"; }

if [[ $chapter_name != pcf ]]; then
  # 11 or 12 set as the chapter is; instructions per frame, per map texel, per shaded pixel.
  if [[ $chapter_name == point ]]; then
    logl_texels=$((6 * 1024 * 1024))
    logl_label="LearnOpenGL 3.2.1 point shadows"
    matched=(--size 800x600 --set cube.size=1024 --set cube.store=distance --set light.near=1
             --set light.far=25 --set cube.filter=nearest --set bias.world=0.05
             --set bias.normal=0 --set shadow.cache=false)
    configs=("six faces, every frame|--set cube.skip=false"
             "faces skipped where empty or unseen|--set cube.skip=true"
             "one layered pass, as the chapter|--set cube.skip=false --set cube.passes=layered")
    unmatched="scene (its room of cubes vs the bulb preset); the chapter's light moves every frame"
  else
    logl_texels=$((5 * 4096 * 4096))
    logl_label="LearnOpenGL guest 2021 CSM"
    matched=(--size 800x600 --set cascades.fit=slice --set cascades.snap=false --set cascades.blend=0
             --set shadow.cache=false)
    configs=("4 cascades of 1024, maps every frame|--set cascades.size=1024"
             "4 cascades of 2048, maps every frame|--set cascades.size=2048")
    unmatched="scene (its cubes on a plane vs the street preset); filter (its 3x3 PCF of 9 taps vs one"
    unmatched+=" linear compare); cascades (its 5 of 4096 vs at most 4 of 2048)"
  fi
  printf 'instructions per frame (callgrind, llvmpipe, 800x600), M: depth pass + lit pass + outside them\n'
  printf '  %-44s %7.2f = %6.2f + %6.2f + %4.2f   %7.2f per map texel, %6.1f per shaded pixel (%d px)\n' \
    "$logl_label" "$(M "$logl_ir")" "$(M "$logl_depth")" "$(M "$logl_lit")" "$(M "$logl_rest")" \
    "$(python3 -c "print($logl_depth / $logl_texels)")" \
    "$(python3 -c "print($logl_lit / max(${logl_pixels:-0}, 1))")" "${logl_pixels:-0}"
  for c in "${configs[@]}"; do
    IFS='|' read -r label extra <<<"$c"
    read -ra more <<<"$extra"
    out=$("$repo/scripts/frame_instructions.sh" "$ours" "${matched[@]}" "${more[@]}")
    total=$(sed -nE 's/^frame ([0-9.]+) M.*/\1/p' <<<"$out")
    read -r -a p <<<"$(sed -nE 's/^passes in the order drawn: frame ([0-9. +]+) M, ([0-9.]+) M after them.*/\1 \2/p' <<<"$out" | tr -d +)"
    [[ ${#p[@]} -ge 2 ]] || { echo "learnopengl_side_by_side: $ours ($label): no passes in: $out" >&2; exit 1; }
    # The last pass is the eye's, every one before it the maps' (with the frame's start).
    rest=${p[-1]} eye=${p[-2]}
    maps=$(python3 -c "print(sum(map(float, '${p[*]:0:${#p[@]}-2}'.split() or [0])))")
    "$lesson" --headless --no-truth --frames 1 "${matched[@]}" "${more[@]}" --out /dev/null \
      --report "$work/r.json" >/dev/null
    read -r texels pixels < <(python3 - "$work/r.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
c, p = r['counters'], r['params']
if 'cube_faces_rendered' in c:
    texels = c['cube_faces_rendered'] * int(p['cube.size']) ** 2
else:
    texels = c['cascade_renders'] * int(p['cascades.size']) ** 2
print(texels, c['eye']['fragments_passed'])
PY
)
    printf '  %-44s %7.2f = %6.2f + %6.2f + %4.2f   %7.2f per map texel, %6.1f per shaded pixel (%d px)  %.2fx\n' \
      "$ours, $label" "$total" "$maps" "$eye" "$rest" "$(python3 -c "print($maps * 1e6 / max($texels, 1))")" \
      "$(python3 -c "print($eye * 1e6 / max($pixels, 1))")" "$pixels" "$(python3 -c "print($total * 1e6 / $logl_ir)")"
  done
  echo "not matched: $unmatched"
  exit 0
fi

config=(--size 800x600 --set scene=cubes --set inset=false --set pcf.count=false
        --set pcf.mode=grid --set pcf.taps=9 --set pcf.radius=1.5)
declare -A ours passes
for name in compare fetch gather best one; do
  case $name in
    best) flags=("${config[@]}" --set pcf.early_out=true) ;;
    one) flags=("${config[@]}" --set pcf.mode=none) ;;
    *) flags=("${config[@]}" --set pcf.early_out=false --set shadow.cache=false --set pcf.lookup=$name) ;;
  esac
  out=$("$repo/scripts/frame_instructions.sh" 05_pcf_dithered "${flags[@]}")
  ours[$name]=$(sed -nE 's/^frame ([0-9.]+) M.*/\1/p' <<<"$out")
  passes[$name]=$(sed -nE 's/^passes in the order drawn: frame ([0-9. +]+) M, ([0-9.]+) M after them.*/\1 \2/p' <<<"$out")
  [[ -n ${passes[$name]} ]] || { echo "learnopengl_side_by_side: 05 ($name): no passes in: $out" >&2; exit 1; }
  [[ $name == compare ]] && off=$(sed -nE '1s/.*shadow.off frame ([0-9.]+) M,.*/\1/p' <<<"$out")
done
printf 'instructions per frame (callgrind, llvmpipe, 800x600), M: depth pass + lit pass + outside them\n'
printf '  %-34s %7.2f = %5.2f + %5.2f + %4.2f\n' 'LearnOpenGL 3.1.3' "$(M "$logl_ir")" "$(M "$logl_depth")" \
  "$(M "$logl_lit")" "$(M "$logl_rest")"
for name in compare fetch gather best one; do
  case $name in
    best) label="05, early out, map cached" ;;
    one) label="05, one lookup, map cached" ;;  # pcf.mode=none: a hard shadow, for scale
    *) label="05, every tap, pcf.lookup=$name" ;;
  esac
  read -r -a p <<<"${passes[$name]//+/}"
  # A cached map draws no depth pass: the frame is the eye pass.
  [[ ${#p[@]} -eq 2 ]] && p=(0 "${p[@]}")
  printf '  %-34s %7.2f = %5.2f + %5.2f + %4.2f  %.2fx LearnOpenGL\n' "$label" "${ours[$name]}" \
    "${p[0]}" "${p[1]}" "${p[2]}" "$(python3 -c "print(${ours[$name]} * 1e6 / $logl_ir)")"
done
printf '  %-34s %7.2f = %5.2f + %5.2f  (the eye pass without a lookup)\n' "05, shadow.off" "$off" 0 "$off"

# Timed: rounds alternate the two programs; each round's median frame, then the median ratio.
ratios=()
for ((r = 0; r < rounds; ++r)); do
  logl_ms=$(logl_run "$work/logl" 2>&1 >/dev/null | awk '/^harness frame_ms/ {print $3}' |
            tail -n +3 | sort -n | median)
  "$lesson" --headless --no-truth --frames "$frames" "${config[@]}" --set pcf.early_out=false \
    --set shadow.cache=false --out /dev/null --report "$work/r.json" >/dev/null
  our_ms=$(python3 -c "import json; print(json.load(open('$work/r.json'))['frame_ms'])")
  ratios+=("$(python3 -c "print($our_ms / $logl_ms)")")
  printf 'round %d: LearnOpenGL %.2f ms, 05 (compare, every tap) %.2f ms\n' $((r + 1)) "$logl_ms" "$our_ms"
done
printf 'timed: 05 / LearnOpenGL, median of %d rounds: %.2fx\n' "$rounds" \
  "$(printf '%s\n' "${ratios[@]}" | sort -n | median)"
