#!/usr/bin/env bash
# Lesson 05 against LearnOpenGL's shadow-mapping chapter (3.1.3, its 3x3 PCF) on the same work,
# on this machine's llvmpipe: instructions per frame (callgrind, deterministic) and frame times
# over interleaved rounds. It fetches nothing: give it a LearnOpenGL checkout.
#
#   scripts/learnopengl_side_by_side.sh [LEARNOPENGL_DIR] [--frames N] [--rounds R]
#
# The chapter is built from the checkout as it is, against the system's GLFW and GLM, with a
# small harness applied to a copy of its main loop (shaders and draw calls untouched): N frames
# then exit, no vsync, and each frame bracketed by glFinish with its time on stderr. Lesson 05
# runs LearnOpenGL's configuration (its cubes, 800x600, a 3x3 grid over adjacent texels, every
# tap, the map rendered every frame) with each pcf.lookup, and its best setting at the same
# error (the early out, the map cached). Needs valgrind, xvfb-run, g++ and a build
# (cmake --build build --target 05_pcf_dithered).
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
logl="" frames=6 rounds=5
while [[ $# -gt 0 ]]; do
  case $1 in
    --frames) frames=$2; shift 2 ;;
    --rounds) rounds=$2; shift 2 ;;
    -h|--help) sed -n 2,14p "${BASH_SOURCE[0]}"; exit 0 ;;
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
once('glfwMakeContextCurrent(window);', 'glfwMakeContextCurrent(window);\n    glfwSwapInterval(0);')
once('while (!glfwWindowShouldClose(window))',
     'for (int harness_frame = 0; harness_frame < %s && !glfwWindowShouldClose(window); ++harness_frame)' % frames)
once('        processInput(window);\n',
     '        processInput(window);\n        glFinish();\n'
     '        const auto harness_t0 = std::chrono::steady_clock::now();\n')
once('        glfwSwapBuffers(window);',
     '        glFinish();\n        std::fprintf(stderr, "harness frame_ms %.4f\\n", std::chrono::duration<double, std::milli>('
     'std::chrono::steady_clock::now() - harness_t0).count());\n        glfwSwapBuffers(window);')
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

# Instructions: a dump before each glfwSwapBuffers holds a frame's work (the swap itself is a
# few thousand instructions: llvmpipe's picture is presented by X), the first start-up too;
# the median of the frames after the first two.
LP_NUM_THREADS=0 logl_run valgrind --tool=callgrind --dump-before=glfwSwapBuffers \
  --callgrind-out-file="$work/cg.out" "$work/logl" \
  >/dev/null 2>"$work/valgrind.log" || { tail "$work/valgrind.log" >&2; exit 1; }
logl_ir=$(python3 - "$work" <<'PY'
import glob, re, statistics, sys
frames = []
for f in glob.glob(sys.argv[1] + '/cg.out.*'):
    text = open(f).read()
    if re.search(r'^desc: Trigger: --dump-before=glfwSwapBuffers', text, re.M):
        frames.append((int(f.rsplit('.', 1)[1]), int(re.search(r'^summary: (\d+)', text, re.M).group(1))))
steady = [ir for _, ir in sorted(frames)[2:]]
if not steady:
    sys.exit('learnopengl_side_by_side: no steady frame dumped; run with --frames 4 or more')
print(statistics.median(steady))
PY
)
config=(--size 800x600 --set scene=cubes --set inset=false --set pcf.count=false
        --set pcf.mode=grid --set pcf.taps=9 --set pcf.radius=1.5)
declare -A ours
for name in compare fetch gather best; do
  case $name in
    best) flags=("${config[@]}" --set pcf.early_out=true) ;;
    *) flags=("${config[@]}" --set pcf.early_out=false --set shadow.cache=false --set pcf.lookup=$name) ;;
  esac
  line=$("$repo/scripts/frame_instructions.sh" 05_pcf_dithered "${flags[@]}")
  ours[$name]=$(sed -E 's/^frame ([0-9.]+) M.*/\1/' <<<"$line")
done
printf 'instructions per frame (callgrind, llvmpipe, 800x600):\n'
printf '  %-34s %8.2f M\n' 'LearnOpenGL 3.1.3' "$(python3 -c "print($logl_ir / 1e6)")"
for name in compare fetch gather best; do
  label=$([[ $name == best ]] && echo "05, early out, map cached" || echo "05, every tap, pcf.lookup=$name")
  printf '  %-34s %8.2f M  %.2fx LearnOpenGL\n' "$label" "${ours[$name]}" \
    "$(python3 -c "print(${ours[$name]} * 1e6 / $logl_ir)")"
done

# Timed: rounds alternate the two programs; each round's median frame, then the median ratio.
ratios=()
for ((r = 0; r < rounds; ++r)); do
  logl_ms=$(logl_run "$work/logl" 2>&1 >/dev/null | awk '/harness frame_ms/ {print $3}' |
            tail -n +3 | sort -n | median)
  "$lesson" --headless --no-truth --frames "$frames" "${config[@]}" --set pcf.early_out=false \
    --set shadow.cache=false --out /dev/null --report "$work/r.json" >/dev/null
  our_ms=$(python3 -c "import json; print(json.load(open('$work/r.json'))['frame_ms'])")
  ratios+=("$(python3 -c "print($our_ms / $logl_ms)")")
  printf 'round %d: LearnOpenGL %.2f ms, 05 (compare, every tap) %.2f ms\n' $((r + 1)) "$logl_ms" "$our_ms"
done
printf 'timed: 05 / LearnOpenGL, median of %d rounds: %.2fx\n' "$rounds" \
  "$(printf '%s\n' "${ratios[@]}" | sort -n | median)"
