#!/usr/bin/env bash
# Lesson 05 against LearnOpenGL's shadow-mapping chapter (3.1.3, its 3x3 PCF) on the same work,
# on this machine's llvmpipe: instructions per frame and per pass (callgrind, deterministic) and
# frame times over interleaved rounds. It fetches nothing: give it a LearnOpenGL checkout.
#
#   scripts/learnopengl_side_by_side.sh [LEARNOPENGL_DIR] [--frames N] [--rounds R]
#
# The chapter is built from the checkout as it is, against the system's GLFW and GLM, with a
# small harness applied to a copy of its main loop (shaders and draw calls untouched): N frames
# then exit, no vsync, and the frame, its depth pass and its lit pass each bracketed by
# glFinish, their times on stderr. Lesson 05 runs LearnOpenGL's configuration (its cubes,
# 800x600, a 3x3 grid over adjacent texels, every tap, the map rendered every frame) with each
# pcf.lookup, its best setting at the same error (the early out, the map cached), one lookup a
# pixel (pcf.mode=none, for scale) and shadow.off (no lookup). Needs valgrind, xvfb-run, g++ and
# a build (cmake --build build --target 05_pcf_dithered).
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
logl="" frames=6 rounds=5
while [[ $# -gt 0 ]]; do
  case $1 in
    --frames) frames=$2; shift 2 ;;
    --rounds) rounds=$2; shift 2 ;;
    -h|--help) sed -n 2,15p "${BASH_SOURCE[0]}"; exit 0 ;;
    -*) echo "learnopengl_side_by_side: unknown option $1 (--frames N, --rounds R)" >&2; exit 2 ;;
    *) logl=$1; shift ;;
  esac
done
[[ $frames =~ ^[0-9]+$ && $frames -ge 4 ]] || { echo "learnopengl_side_by_side: --frames must be 4 or more" >&2; exit 2; }
[[ $rounds =~ ^[0-9]+$ && $rounds -ge 1 ]] || { echo "learnopengl_side_by_side: --rounds must be 1 or more" >&2; exit 2; }
if [[ -z $logl ]]; then
  cat <<'EOF'
learnopengl_side_by_side: no LearnOpenGL checkout given, nothing measured.
  git clone https://github.com/JoeyDeVries/LearnOpenGL /tmp/LearnOpenGL
  scripts/learnopengl_side_by_side.sh /tmp/LearnOpenGL
(measured at its commit a545a70; docs/MEASUREMENTS.md has the table)
EOF
  exit 0
fi
[[ -d $logl ]] || { echo "learnopengl_side_by_side: $logl is not a folder" >&2; exit 2; }
logl=$(cd "$logl" && pwd)  # its programs run from their chapter's folder
[[ $logl != *[\"\\]* ]] || { echo "learnopengl_side_by_side: a path with quotes or backslashes" >&2; exit 2; }
chapter=$logl/src/5.advanced_lighting/3.1.3.shadow_mapping
[[ -f $chapter/shadow_mapping.cpp ]] || { echo "learnopengl_side_by_side: $chapter/shadow_mapping.cpp not found" >&2; exit 2; }
lesson=$repo/build/05_pcf_dithered
[[ -x $lesson ]] || { echo "learnopengl_side_by_side: $lesson not built" >&2; exit 2; }
for tool in valgrind xvfb-run g++ python3; do
  command -v $tool >/dev/null || { echo "learnopengl_side_by_side: needs $tool" >&2; exit 2; }
done

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# The harness, on a copy: its model.h (assimp) is not used by this chapter.
python3 - "$chapter/shadow_mapping.cpp" "$work/main.cpp" "$frames" <<'PY'
import sys
src, out, frames = open(sys.argv[1]).read(), sys.argv[2], sys.argv[3]
def once(old, new):
    global src
    assert src.count(old) == 1, old
    src = src.replace(old, new)
once('#include <learnopengl/model.h>\n', '#include <chrono>\n#include <cstdio>\n')
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
once('        glBindFramebuffer(GL_FRAMEBUFFER, 0);\n\n        // reset viewport',
     '        glBindFramebuffer(GL_FRAMEBUFFER, 0);\n        harness_finish();\n'
     '        const auto harness_t1 = std::chrono::steady_clock::now();\n\n        // reset viewport')
once('        glfwSwapBuffers(window);',
     '        harness_finish();\n        const auto harness_t2 = std::chrono::steady_clock::now();\n'
     '        const auto harness_ms = [](auto a, auto b) { return std::chrono::duration<double, std::milli>(b - a).count(); };\n'
     '        std::fprintf(stderr, "harness frame_ms %.4f depth_ms %.4f lit_ms %.4f\\n", harness_ms(harness_t0, harness_t2),\n'
     '                     harness_ms(harness_t0, harness_t1), harness_ms(harness_t1, harness_t2));\n'
     '        glfwSwapBuffers(window);')
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
M() { python3 -c "print(f'{$1 / 1e6:.2f}')"; }
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
