#!/bin/sh
# The GPU check: one command on a machine that has only the bundle (scripts/bundle.sh) and a
# GPU driver reached through glvnd. Everything goes into one folder; summary.md says what it
# found (docs/GPU.md explains every file). At most 7.8 minutes: each step has its own limit
# (machine 15 s, probe 30 s, views 130 s, studies 95 + 40 s, 06/07 40 + 40 s, 08 40 s,
# 11's six and layered passes 10 + 10 s, 12 15 s).
#
#   ./gpu_check.sh [--out DIR] [--device N] [--backend NAME] [--short]
#
#   --out DIR      the output folder (default ./gpu_check-<date>)
#   --device N     the EGL device (default 0; a wrong one lists those there are)
#   --backend NAME egl-device (default), or egl / osmesa where the machine has those
#   --short        a few configurations at 160x120, one frame, one round: for testing the
#                  script itself (tests/gpu_check_test.sh runs it so on llvmpipe)
#
# Exit 0: every step ran and nothing failed (a study or views cut short by their time limit
# are named in the last line, not failures). Exit 1: something failed (a view or error number
# outside the tolerance, a GL error, a program that did not run; the last line counts them,
# summary.md says which); the output folder is complete either way. A case whose reference is
# not in the bundle (bundle.sh --no-references, or --short's) is rendered and checked for GL
# errors but not compared, and the check says so once.
set -u

bundle=$(cd "$(dirname "$0")" && pwd)
out=$PWD/gpu_check-$(date -u +%Y%m%d-%H%M%S)
device=0
backend=egl-device
short=0
while [ $# -gt 0 ]; do
  case $1 in
    --out) out=$2; shift 2 ;;
    --device) device=$2; shift 2 ;;
    --backend) backend=$2; shift 2 ;;
    --short) short=1; shift ;;
    *) echo "gpu_check.sh: unknown option '$1' (--out DIR, --device N, --backend NAME, --short)" >&2
       exit 2 ;;
  esac
done
mkdir -p "$out" || exit 2
out=$(cd "$out" && pwd)
bin=$bundle/bin
share=$bundle/share/shadows
start=$(date +%s)
log() { echo "$*" | tee -a "$out/log.txt"; }
elapsed() { echo $(($(date +%s) - start)); }

# A machine with the driver but without glvnd's libEGL.so.1: the bundle's copy (bundle.sh
# --glvnd), and the driver's vendor file where glvnd finds none.
if ldd "$bin/shadows_lessons" | grep -q 'libEGL.so.1 => not found' && [ -d "$bundle/glvnd" ]; then
  LD_LIBRARY_PATH=$bundle/glvnd/usr/lib/x86_64-linux-gnu${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
  export LD_LIBRARY_PATH
  log "using the bundle's glvnd loader ($bundle/glvnd)"
fi
if [ -z "${__EGL_VENDOR_LIBRARY_FILENAMES:-}" ] && [ -z "${__EGL_VENDOR_LIBRARY_DIRS:-}" ] &&
   ! ls /usr/share/glvnd/egl_vendor.d/*.json /etc/glvnd/egl_vendor.d/*.json > /dev/null 2>&1 &&
   ldconfig -p 2> /dev/null | grep -q libEGL_nvidia.so.0; then
  printf '{"file_format_version": "1.0.0", "ICD": {"library_path": "libEGL_nvidia.so.0"}}\n' \
    > "$out/10_nvidia.json"
  __EGL_VENDOR_LIBRARY_FILENAMES=$out/10_nvidia.json
  export __EGL_VENDOR_LIBRARY_FILENAMES
  log "no glvnd vendor file on this machine: using $out/10_nvidia.json"
fi

device_args="--backend $backend"
[ "$backend" = egl-device ] && device_args="$device_args --device $device"

# ---------------------------------------------------------------- the machine
{
  echo "date: $(date -u)"
  echo "uname: $(uname -a)"
  echo "glibc: $(ldd --version 2>&1 | head -1)"
  echo "cpus: $(nproc 2> /dev/null)"
  command -v nvidia-smi > /dev/null && nvidia-smi -L && nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv
  echo "EGL devices (a device that is not there lists them):"
  timeout 15 "$bin/03_shadow_map_basic" --headless --backend egl-device --device 63 2>&1
  echo "libraries of bin/shadows_lessons:"
  ldd "$bin/shadows_lessons"
} > "$out/machine.txt" 2>&1

# ---------------------------------------------------------------- can it render at all?
# shellcheck disable=SC2086
if ! timeout 30 "$bin/03_shadow_map_basic" --headless $device_args --size 320x240 --frames 3 \
     --out "$out/probe.png" --report "$out/probe.json" > "$out/probe.txt" 2>&1; then
  log "gpu_check: lesson 03 does not render with $device_args:"
  cat "$out/probe.txt" | tee -a "$out/log.txt"
  printf '# GPU check: failed\n\nLesson 03 does not render with `%s`:\n\n```\n%s\n```\n' \
    "$device_args" "$(cat "$out/probe.txt")" > "$out/summary.md"
  exit 1
fi
field() { sed -n "s/^ *\"$1\": \"\([^\"]*\)\".*/\1/p" "$out/probe.json" | head -1; }
renderer=$(field renderer)
vendor=$(field vendor)
device_name=$(awk '/"device": \{/ { inside = 1 } inside && /"name":/ { sub(/.*"name": "/, ""); sub(/".*/, ""); print; exit }' "$out/probe.json")
log "rendering on: $renderer ($vendor; $backend ${device_name:+device $device: $device_name})"

# ---------------------------------------------------------------- every lesson's views
# Each case (share/shadows/cases.txt): every view as a picture and the shaded view's report,
# against the llvmpipe run of the same configuration (share/shadows/reference/CASE).
mkdir -p "$out/views"
cases=$share/cases.txt
[ $short = 1 ] && cases=$share/cases_short.txt
# A case without its reference (a bundle made with --no-references, or --short's few) is
# rendered and checked for GL errors, not compared: said once here, per case in its file.
total=$(grep -c . "$cases")
unreferenced=0
while read -r lesson case sets; do
  [ -d "$share/reference/$case" ] || unreferenced=$((unreferenced + 1))
done < "$cases"
if [ ! -d "$share/reference" ]; then
  log "views: this bundle has no references (bundle.sh --no-references): the $total cases are rendered and checked for GL errors, not compared with llvmpipe"
elif [ $unreferenced -gt 0 ]; then
  log "views: $unreferenced of the $total cases have no reference in this bundle (bundle.sh --short?): those are rendered and checked for GL errors, not compared with llvmpipe"
fi
views_deadline=$(($(date +%s) + 130))
while read -r lesson case sets; do
  left=$((views_deadline - $(date +%s)))
  if [ $left -le 0 ]; then
    echo "SKIPPED: out of the views' 130 s" > "$out/views/$case.txt"
    continue
  fi
  set_args=""
  for s in $sets; do set_args="$set_args --set $s"; done
  reference="--reference $share/reference/$case"
  [ -d "$share/reference/$case" ] || reference=""
  # shellcheck disable=SC2086
  timeout $left "$bin/flavour_views" "$lesson" "$out/views/$case" $reference \
    $device_args --counters-differ $set_args > "$out/views/$case.txt" 2>&1
  status=$?
  if [ -z "$reference" ]; then
    echo "NOT COMPARED: no reference for $case in this bundle" >> "$out/views/$case.txt"
    # Compared, the report's GL errors are checked against the reference's; here on their own.
    [ $status = 0 ] && ! grep -q '"gl_errors": 0' "$out/views/$case/report.json" 2> /dev/null &&
      echo "FAIL report: gl_errors not 0" >> "$out/views/$case.txt"
  fi
  echo "exit $status" >> "$out/views/$case.txt"
done < "$cases"
log "views: done at $(elapsed) s"

# ---------------------------------------------------------------- the studies and sweeps
# Each bench_sweep run has a time limit, so the whole check stays under 8 minutes.
sweep() {  # sweep NAME LIMIT_S [bench_sweep flags]; into $SWEEP_DIR (default bench/)
  name=$1 limit=$2 dir=${SWEEP_DIR:-$out/bench}
  shift 2
  mkdir -p "$dir"
  if [ $short = 1 ]; then
    set -- "$@" --size 160x120 --frames 1 --rounds 1
  fi
  # shellcheck disable=SC2086
  timeout "$limit" "$bin/bench_sweep" --lesson "$name" --out-dir "$dir" --no-plot \
    $device_args "$@" > "$dir/$name.log" 2>&1
  status=$?
  [ $status = 124 ] && echo "TIMEOUT after $limit s" >> "$dir/$name.log"
  log "bench ${dir#"$out/"}/$name: exit $status at $(elapsed) s"
  case $status in
    0) ;;
    124) studies_timed_out="$studies_timed_out $name" ;;
    *) studies_failed="$studies_failed $name" ;;
  esac
}
studies_failed=""
studies_timed_out=""
mkdir -p "$out/bench"
if [ $short = 1 ]; then
  # Google Benchmark's names: sweep/scene/axis:value/... (the last word of each parameter).
  sweep shadow_cost 60 '--benchmark_filter=/cubes/.*/lesson_tag:03/'
  sweep pcf_cost 60 '--benchmark_filter=/cubes/'
  sweep 06_dual_texture_8bit 60 '--benchmark_filter=/dueling/size:256/.*/depth_bits:24/'
  sweep 08_atmospherics 60 '--benchmark_filter=/slices:(16|32)/downsample:2/'
  cube='/bulb/size:64/store:distance/filter:nearest/'
  cascades='/street/count:(1|4)/fit:sphere/snap:true/'
else
  sweep shadow_cost 95
  sweep pcf_cost 40
  sweep 06_dual_texture_8bit 40
  sweep 07_multidigit_16bit 40
  sweep 08_atmospherics 40
  cube='/bulb/size:512/'
  cascades='/street/'
fi
# Lesson 11's cube rendered every frame as six passes and as one layered pass (a geometry
# shader: desktop GL), each a sweep of its own; lesson 12's cascades, by count, fit and snap.
for passes in six layered; do
  SWEEP_DIR=$out/bench/11_$passes sweep 11_omni_cube 10 "--benchmark_filter=$cube" \
    --set cube.passes=$passes
done
sweep 12_cascades 15 "--benchmark_filter=$cascades"

# ---------------------------------------------------------------- what failed
# Every FAIL line of the views, a flavour_views that ended otherwise than by its verdict (a
# crash, a bad case), and a study that did not finish for another reason than its time limit.
failures=0
failed_cases=""
cut_short=""
compared=0
while read -r lesson case sets; do
  f=$out/views/$case.txt
  [ -f "$f" ] || continue
  if grep -q '^SKIPPED' "$f" || grep -q '^exit 124$' "$f"; then
    cut_short="$cut_short $case"
  fi
  grep -q '^NOT COMPARED' "$f" || grep -q '^SKIPPED' "$f" || compared=$((compared + 1))
  n=$(grep -c '^FAIL' "$f")
  grep -q '^exit \(0\|1\|124\)$' "$f" || grep -q '^SKIPPED' "$f" || n=$((n + 1))
  if [ "$n" -gt 0 ]; then
    failures=$((failures + n))
    failed_cases="$failed_cases $case"
    first=$(grep '^FAIL' "$f" | head -1 | sed 's/^FAIL //')
    log "FAIL views $case: ${first:-$(tail -1 "$f")} ($n failures in views/$case.txt)"
  fi
done < "$cases"
for name in $studies_failed; do
  failures=$((failures + 1))
  log "FAIL bench $name: $(grep -v '^ *$' "$out/bench/$name.log" | tail -1)"
done

# ---------------------------------------------------------------- summary.md
# A CSV reader that knows quoted fields ("llvmpipe (LLVM 15.0.6, 256 bits)"); median of COLUMN
# over the rows where every NAME=VALUE holds; "nan" when none.
median() {  # median FILE COLUMN [NAME=VALUE ...]
  [ -f "$1" ] || { echo nan; return; }
  file=$1 column=$2
  shift 2
  awk -v column="$column" -v conditions="$*" '
    function split_csv(line, f,   n, i, c, q, cell) {
      n = 0; cell = ""; q = 0
      for (i = 1; i <= length(line); i++) {
        c = substr(line, i, 1)
        if (q) { if (c == "\"") { if (substr(line, i + 1, 1) == "\"") { cell = cell c; i++ } else q = 0 } else cell = cell c }
        else if (c == "\"") q = 1
        else if (c == ",") { f[++n] = cell; cell = "" }
        else cell = cell c
      }
      f[++n] = cell
      return n
    }
    NR == 1 { n = split_csv($0, head); for (i = 1; i <= n; i++) at[head[i]] = i
              m = split(conditions, cond, " "); next }
    { split_csv($0, f); ok = 1
      for (k = 1; k <= m; k++) { eq = index(cond[k], "=")
        if (f[at[substr(cond[k], 1, eq - 1)]] != substr(cond[k], eq + 1)) ok = 0 }
      if (ok && f[at[column]] != "") v[++count] = f[at[column]] + 0 }
    END {
      if (count == 0) { print "nan"; exit }
      for (i = 1; i <= count; i++) for (j = i + 1; j <= count; j++) if (v[j] < v[i]) { t = v[i]; v[i] = v[j]; v[j] = t }
      printf "%.4g\n", (count % 2) ? v[(count + 1) / 2] : (v[count / 2] + v[count / 2 + 1]) / 2 }' "$file"
}
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (a == "nan" || b == "nan" || b == 0) print "nan"; else printf "%.2f", a / b }'; }
verdict() {  # verdict RATIO LIMIT
  awk -v r="$1" -v l="$2" 'BEGIN { if (r == "nan") print "not measured"; else if (r + 0 <= l + 0) print "**met**"; else print "missed" }'
}

gpu_cost=$out/bench/shadow_cost.csv
cpu_cost=$share/llvmpipe/bench_shadow_cost.csv
gpu_pcf=$out/bench/pcf_cost.csv
cpu_pcf=$share/llvmpipe/bench_pcf_cost.csv
cost_ratio() {  # cost_ratio CSV CACHE: lesson 03's frame over its unshadowed frame, medians
  ratio "$(median "$1" frame_ms lesson=03_shadow_map_basic shadow.cache="$2" shadow.off=false)" \
        "$(median "$1" frame_ms lesson=03_shadow_map_basic shadow.cache="$2" shadow.off=true)"
}
pcf_ratio() {  # pcf_ratio CSV KERNEL SCENE: 05's eye pass over the unshadowed eye pass
  ratio "$(median "$1" pass_ms.eye kernel="$2" scene="$3" shadow.off=false)" \
        "$(median "$1" pass_ms.eye kernel="$2" scene="$3" shadow.off=true)"
}
target_row() {  # target_row TEXT LIMIT GPU_RATIO LLVMPIPE_RATIO
  echo "| $1 | ${3}× | ${4}× | ≤ ${2}× | $(verdict "$3" "$2") |"
}

{
  echo "# GPU check: $renderer"
  echo
  echo "Vendor $vendor; backend $backend${device_name:+, device $device ($device_name)}; $(date -u);"
  echo "$(elapsed) s in all$( [ $short = 1 ] && echo ' (--short: a few configurations, 160x120, numbers not comparable)')."
  echo "Every file named here is in this folder; docs/GPU.md (GPU.md in the bundle) explains them."
  echo
  if [ $failures -gt 0 ]; then
    echo "**Result: $failures failures** (views:${failed_cases:- none}; studies:${studies_failed:- none}); the log under Steps names each."
  else
    echo "**Result: no failures.**"
  fi
  [ $compared -lt "$total" ] &&
    echo "$((total - compared)) of the $total cases were not compared with llvmpipe (no reference in the bundle, or out of time)."
  [ -n "$studies_timed_out" ] && echo "Studies stopped at their time limit:$studies_timed_out (their rows read \"not measured\")."
  echo
  echo "## Issue 10's targets (bench/shadow_cost.csv, bench/pcf_cost.csv)"
  echo
  echo "Medians over the presets (03) or per preset (05's eye pass); llvmpipe: the CSVs the README quotes."
  echo
  echo "| target | this run | llvmpipe | limit | verdict |"
  echo "|---|---|---|---|---|"
  target_row "03 defaults, map cached: frame / unshadowed frame" 1.15 \
    "$(cost_ratio "$gpu_cost" true)" "$(cost_ratio "$cpu_cost" true)"
  target_row "03 defaults, map every frame: frame / unshadowed frame" 1.4 \
    "$(cost_ratio "$gpu_cost" false)" "$(cost_ratio "$cpu_cost" false)"
  for scene in cubes torus_pyramid; do
    target_row "05 3×3 grid, every tap, $scene: eye pass / unshadowed" 1.6 \
      "$(pcf_ratio "$gpu_pcf" grid3x3 $scene)" "$(pcf_ratio "$cpu_pcf" grid3x3 $scene)"
    target_row "05 3×3 grid, early out, $scene: eye pass / unshadowed" 1.25 \
      "$(pcf_ratio "$gpu_pcf" grid3x3_early_out $scene)" "$(pcf_ratio "$cpu_pcf" grid3x3_early_out $scene)"
    for lookup in fetch gather; do  # issue 40: the same grid read another way (llvmpipe: README)
      target_row "05 3×3 grid, every tap, pcf.lookup=$lookup, $scene: eye pass / unshadowed" 1.6 \
        "$(pcf_ratio "$gpu_pcf" grid3x3_$lookup $scene)" "$(pcf_ratio "$cpu_pcf" grid3x3_$lookup $scene)"
    done
    target_row "05 one tap (none), $scene: eye pass / unshadowed" 1.15 \
      "$(pcf_ratio "$gpu_pcf" none $scene)" "$(pcf_ratio "$cpu_pcf" none $scene)"
  done
  echo
  echo "Every lesson's cost (frame / unshadowed frame, map cached and every frame):"
  echo
  echo "| lesson | cached | every frame | llvmpipe cached | llvmpipe every frame |"
  echo "|---|---|---|---|---|"
  for l in 03_shadow_map_basic 04_bias_offset 05_pcf_dithered 06_dual_texture_8bit 07_multidigit_16bit 08_atmospherics; do
    row="| $l"
    for csv in "$gpu_cost" "$cpu_cost"; do
      for cache in true false; do
        row="$row | $(ratio "$(median "$csv" frame_ms lesson=$l shadow.cache=$cache shadow.off=false)" \
                            "$(median "$csv" frame_ms lesson=$l shadow.cache=$cache shadow.off=true)")×"
      done
    done
    echo "$row |"
  done
  echo
  echo "## Pictures and error numbers against llvmpipe (views/)"
  echo
  echo "Per configuration: views whose pictures moved more than the golden tolerance (16 pixels),"
  echo "the worst view, error numbers outside 0.02 points, counters that differ (NOTE lines)."
  echo
  echo "| configuration | views within tolerance | worst view: pixels moved, largest difference | error numbers off | counters differing | GL errors or failures |"
  echo "|---|---|---|---|---|---|"
  while read -r lesson case sets; do
    f=$out/views/$case.txt
    [ -f "$f" ] || continue
    if grep -q '^NOT COMPARED' "$f"; then
      other=$(grep -c '^FAIL ' "$f")
      grep -q '^exit 124$' "$f" && other="stopped (time)"
      echo "| $case | not compared: no reference in the bundle | | | | $other |"
      continue
    fi
    views=$(grep -c '^view ' "$f")
    moved=$(grep -c '^FAIL .*pixels differ' "$f")
    worst=$(awk '/^view /{ n = $3 + 0; if (n > best) { best = n; w = $2 " " $3 " px, " $NF } }
                 END { print (w == "" ? "none differs" : w) }' "$f")
    errors=$(grep -c '^FAIL error/' "$f")
    notes=$(grep -c '^NOTE ' "$f")
    other=$(grep '^FAIL ' "$f" | grep -vc 'pixels differ\|^FAIL error/')
    grep -q '^SKIPPED' "$f" && other="skipped (time)"
    grep -q '^exit 124$' "$f" && other="stopped (time)"
    echo "| $case | $((views - moved))/$views | $worst | $errors | $notes | $other |"
  done < "$cases"
  echo
  echo "## 06/07's copy paths (bench/06_dual_texture_8bit.csv, 07_multidigit_16bit.csv)"
  echo
  echo "Median frame ms over the scenes and depth digits; readback pass ms in brackets."
  echo
  for l in 06_dual_texture_8bit 07_multidigit_16bit; do
    csv=$out/bench/$l.csv
    [ -f "$csv" ] || continue
    echo "| $l | shadow.size=256 | 512 | 1024 | 2048 |"
    echo "|---|---|---|---|---|"
    for path in read_pixels copy_texture render_to_texture; do
      row="| $path"
      for size in 256 512 1024 2048; do
        row="$row | $(median "$csv" frame_ms map.path=$path shadow.size=$size) ($(median "$csv" pass_ms.readback map.path=$path shadow.size=$size))"
      done
      echo "$row |"
    done
    echo
  done
  echo "## 11's cube: six passes against one layered pass (bench/11_six/, bench/11_layered/)"
  echo
  echo "The \`bulb\` preset, cube rendered every frame; frame ms (shadow pass ms). On llvmpipe the"
  echo "layered pass was the dearer (101 M against 77 M instructions a frame, 11's README)."
  echo
  echo "| cube.store | cube.filter | six passes | one layered pass | llvmpipe, six passes |"
  echo "|---|---|---|---|---|"
  for store in distance depth; do
    for filter in nearest linear; do
      at="cube.store=$store cube.filter=$filter"
      six=$out/bench/11_six/11_omni_cube.csv layered=$out/bench/11_layered/11_omni_cube.csv
      [ "$(median "$six" frame_ms $at)" = nan ] && [ "$(median "$layered" frame_ms $at)" = nan ] && continue
      echo "| $store | $filter | $(median "$six" frame_ms $at) ($(median "$six" pass_ms.shadow $at)) | $(median "$layered" frame_ms $at) ($(median "$layered" pass_ms.shadow $at)) | $(median "$share/llvmpipe/bench_11_omni_cube.csv" frame_ms cube.size=512 $at) |"
    done
  done
  echo
  echo "## 12's cascades (bench/12_cascades.csv)"
  echo
  echo "The \`street\` preset, cascades rendered every frame; the shimmer is the same on any GPU that"
  echo "draws the same pictures (it is a count of pixels), so it checks the pictures too."
  echo
  echo "| cascades.count | fit | snap | frame ms | shadow pass ms | shimmer % | llvmpipe frame ms | llvmpipe shimmer % |"
  echo "|---|---|---|---|---|---|---|---|"
  for n in 1 2 3 4; do
    for fit in slice sphere; do
      for snap in false true; do
        csv=$out/bench/12_cascades.csv
        at="scene=street cascades.count=$n cascades.fit=$fit cascades.snap=$snap"
        ms=$(median "$csv" frame_ms $at)
        [ "$ms" = nan ] && continue
        ref=$share/llvmpipe/bench_12_cascades.csv
        echo "| $n | $fit | $snap | $ms | $(median "$csv" pass_ms.shadow $at) | $(median "$csv" shimmer_pct $at) | $(median "$ref" frame_ms $at) | $(median "$ref" shimmer_pct $at) |"
      done
    done
  done
  echo
  echo "## 08's slices (bench/08_atmospherics.csv)"
  echo
  echo "| air.slices | air.downsample | frame ms | air pass ms | air rel. RMSE | llvmpipe frame ms |"
  echo "|---|---|---|---|---|---|"
  for n in 16 24 32 48 64 96 128; do
    for d in 1 2 3 4; do
      csv=$out/bench/08_atmospherics.csv
      at="air.slices=$n air.downsample=$d"
      ms=$(median "$csv" frame_ms $at)
      [ "$ms" = nan ] && continue
      echo "| $n | $d | $ms | $(median "$csv" pass_ms.air $at) | $(median "$csv" air_rel_rmse $at) | $(median "$share/llvmpipe/bench_08_atmospherics.csv" frame_ms $at) |"
    done
  done
  echo
  echo "## Steps"
  echo
  sed 's/^/    /' "$out/log.txt"
} > "$out/summary.md"
# The last line: the verdict, what was not checked, where the rest is.
also=""
[ $compared -lt "$total" ] && also="$also; $((total - compared)) of $total cases not compared with llvmpipe"
[ -n "$cut_short" ] && also="$also; views cut short by time:$cut_short"
[ -n "$studies_timed_out" ] && also="$also; studies stopped at their limit:$studies_timed_out"
if [ $failures -gt 0 ]; then
  log "gpu_check: FAILED, $failures failures (views:${failed_cases:- none}; studies:${studies_failed:- none})$also; $out/summary.md ($(elapsed) s)"
  exit 1
fi
log "gpu_check: passed, no failures$also; $out/summary.md ($(elapsed) s)"
