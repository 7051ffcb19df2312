#!/usr/bin/env bash
# Benchmarks: render plate(N) (bench/plate.lua) at 1024x768 on one and on
# all threads, and export it as STL; print Markdown tables of wall time,
# peak memory, the stages (script, build, trace, write; script, mesh, check,
# write) and rays per second or triangles, with the machine and date, for
# docs/performance.md. Wall time includes start-up and the script,
# as a user sees it. Compare ratios within one run: the machines are shared
# and noisy, so each figure is the best of RUNS runs (default 3).
set -euo pipefail
csgray=${1:-build/cli/csgray}
sizes=${SIZES:-"8 16 32 64"}         # render
# export: EXPORT_SIZES, default "8 16 32"
runs=${RUNS:-3}
threads_all=$(nproc)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

# Wall time in milliseconds from the shell's clock (time(1) gives
# hundredths of a second, a tenth of plate(8) on two threads).
elapsed() { awk -v a="$1" -v b="$EPOCHREALTIME" 'BEGIN {printf "%.3f\n", b - a}'; }

echo "Machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), $(free -g | awk '/Mem:/ {print $2}') GiB; $(date -u +%Y-%m-%d); csgray $("$csgray" --version)"
echo
echo "| scene | threads | wall (s) | peak memory (MB) | script (s) | build (s) | trace (s) | write (s) | primary rays/s | shadow rays/s |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
declare -A wall
for n in $sizes; do
  for threads in 1 "$threads_all"; do
    best=""
    for ((r = 0; r < runs; r++)); do
      start=$EPOCHREALTIME
      "$csgray" render bench/plate.lua -D n="$n" -o "$out/plate.png" --size 1024x768 \
        --threads "$threads" --stats >/dev/null 2>"$out/stats"
      seconds=$(elapsed "$start")
      if [ -z "$best" ] || awk -v a="$seconds" -v b="$best" 'BEGIN {exit !(a < b)}'; then
        best=$seconds
        stages=$(sed -n 's/.*script \([0-9.]*\) s, build \([0-9.]*\) s, trace \([0-9.]*\) s, write \([0-9.]*\) s/\1 \2 \3 \4/p' "$out/stats")
        rates=$(sed -n 's/.*primary (\([0-9.]*\) M\/s).*shadow (\([0-9.]*\) M\/s).*/\1 \2/p' "$out/stats")
      fi
    done
    # Peak memory from one more run under time(1), whose own fork and exec
    # would add some 10 ms of serial time to the figures above.
    /usr/bin/time -f "%M" -o "$out/time" "$csgray" render bench/plate.lua -D n="$n" \
      -o "$out/plate.png" --size 1024x768 --threads "$threads" >/dev/null 2>&1
    memory=$(($(tail -1 "$out/time") / 1024))
    read -r script build trace write <<<"$stages"
    read -r primary shadow <<<"$rates"
    wall[$n,$threads]=$best
    printf '| plate(%s) | %s | %s | %d | %s | %s | %s | %s | %s M | %s M |\n' "$n" "$threads" "$best" \
      "$memory" "$script" "$build" "$trace" "$write" "$primary" "$shadow"
  done
done
echo
first=${sizes%% *}
last=${sizes##* }
awk -v a="${wall[$last,1]}" -v b="${wall[$first,1]}" -v n="$last" -v m="$first" \
  'BEGIN {printf "plate(%s) / plate(%s) on one thread: %.2f×\n", n, m, a / b}'
for n in $sizes; do
  awk -v a="${wall[$n,1]}" -v b="${wall[$n,$threads_all]}" -v n="$n" -v t="$threads_all" \
    'BEGIN {printf "plate(%s): %s threads are %.2f× faster than one\n", n, t, a / b}'
done

# Export: plate(N) as a binary STL at the default tolerance. The export
# checks the mesh with CGAL (closed, manifold, outward, no self-intersections)
# before writing, so a written file is a valid one.
echo
echo "| export | wall (s) | peak memory (MB) | script (s) | mesh (s) | check (s) | write (s) | triangles | booleans | valid |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---|"
export_sizes=${EXPORT_SIZES:-"8 16 32"}
for n in $export_sizes; do
  best=""
  for ((r = 0; r < runs; r++)); do
    valid=yes
    /usr/bin/time -f "%e %M" -o "$out/time" \
      "$csgray" export bench/plate.lua -D n="$n" -o "$out/plate.stl" --stats \
      >"$out/stdout" 2>"$out/stats" || valid="no: $(tail -1 "$out/stats")"
    # time(1) puts "Command exited with non-zero status" before the figures.
    read -r seconds kilobytes < <(tail -1 "$out/time")
    if [ -z "$best" ] || awk -v a="$seconds" -v b="$best" 'BEGIN {exit !(a < b)}'; then
      best=$seconds
      stages=$(sed -n 's/.*script \([0-9.]*\) s, mesh \([0-9.]*\) s, check \([0-9.]*\) s, write \([0-9.]*\) s/\1 \2 \3 \4/p' "$out/stats")
      triangles=$(sed -n 's/.*(\([0-9]*\) triangles.*/\1/p' "$out/stdout")
      booleans=$(sed -n 's/.*tessellated, \([0-9]*\) booleans.*/\1/p' "$out/stats")
      memory=$((kilobytes / 1024))
      verdict=$valid
    fi
  done
  read -r script mesh check write <<<"${stages:-- - - -}"
  printf '| plate(%s) | %s | %d | %s | %s | %s | %s | %s | %s | %s |\n' "$n" "$best" "$memory" \
    "$script" "$mesh" "$check" "$write" "${triangles:--}" "${booleans:--}" "$verdict"
done

pairs=${PAIRS:-5}
one_core="taskset -c 0"
median() { sort -n | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
# time_of <command...>: wall seconds, or "failed"
time_of() {
  local start=$EPOCHREALTIME
  if "$@" >/dev/null 2>"$out/err"; then elapsed "$start"; else echo failed; fi
}

# Export against Manifold (its WebAssembly build, bench/manifold/parts.mjs,
# installed by `make bench`): the same geometry with csgray's segment counts,
# written as a binary STL by both, whole process. The two commands alternate,
# PAIRS times (default 5), and the medians are compared: on one core
# (taskset) for every part, and on all cores for plate(32) (Manifold's
# WebAssembly build runs on one either way).
manifold=bench/manifold/parts.mjs
if [ -d bench/manifold/node_modules/manifold-3d ] && command -v node >/dev/null; then
  echo
  echo "| export vs Manifold | cores | csgray median (s) | Manifold median (s) | csgray / Manifold | csgray valid |"
  echo "|---|---:|---:|---:|---:|---|"
  # part:parameter=value:script[:all]; the value goes to parts.mjs too.
  rows="plate:n=8:bench/plate.lua plate:n=16:bench/plate.lua plate:n=32:bench/plate.lua
        shaft_on_hub::bench/parts/shaft_on_hub.lua two_frustums::bench/parts/two_frustums.lua
        frustum_stack::bench/parts/frustum_stack.lua vase:layers=40:examples/vase.lua
        rounded_box::examples/rounded_box.lua pixel_knob::examples/pixel_knob.lua
        knurled_knob::examples/knurled_knob.lua gear:twist=30:bench/parts/gear.lua
        turned_vase::bench/parts/turned_vase.lua plate:n=32:bench/plate.lua:all"
  for row in $rows; do
    IFS=: read -r name parameter script cores <<<"$row"
    pin=$one_core
    label=1
    if [ "$cores" = all ]; then pin=""; label=$threads_all; fi
    define=()
    n=${parameter#*=}
    [ -n "$parameter" ] && define=(-D "$parameter")
    : >"$out/a"; : >"$out/b"
    valid=yes
    for ((r = 0; r < pairs; r++)); do
      t=$(time_of $pin "$csgray" export "$script" "${define[@]}" -o "$out/part.stl")
      [ "$t" = failed ] && valid="no: $(tail -1 "$out/err")" || echo "$t" >>"$out/a"
      t=$(time_of $pin node "$manifold" "$name" $n -o "$out/manifold.stl")
      [ "$t" = failed ] || echo "$t" >>"$out/b"
    done
    a=$(median <"$out/a"); b=$(median <"$out/b")
    ratio=$(awk -v a="$a" -v b="$b" 'BEGIN {if (a == "" || b == "") print "-"; else printf "%.2f", a / b}')
    printf '| %s%s | %s | %s | %s | %s | %s |\n' "$name" "${n:+($n)}" "$label" "${a:--}" "${b:--}" \
      "$ratio" "$valid"
  done
else
  echo
  echo "(export vs Manifold left out: make bench installs manifold-3d into bench/manifold)"
fi

# csgray check: plate(N)'s export held against the exact model at the
# default settings (100 000 points, three 128² ray grids); wall time
# includes making the export in memory.
echo
echo "| check | wall (s) | peak memory (MB) | verdict |"
echo "|---|---:|---:|---|"
check_sizes=${CHECK_SIZES:-"8 16"}
for n in $check_sizes; do
  best=""
  for ((r = 0; r < runs; r++)); do
    verdict=ok
    /usr/bin/time -f "%e %M" -o "$out/time" \
      "$csgray" check bench/plate.lua -D n="$n" >"$out/stdout" 2>&1 || verdict="FAILED"
    read -r seconds kilobytes < <(tail -1 "$out/time")
    if [ -z "$best" ] || awk -v a="$seconds" -v b="$best" 'BEGIN {exit !(a < b)}'; then
      best=$seconds
      memory=$((kilobytes / 1024))
      result=$verdict
    fi
  done
  printf '| plate(%s) | %s | %d | %s |\n' "$n" "$best" "$memory" "$result"
done

# Renders against POV-Ray 3.7 (installed by `make bench`): the involute gear
# (bench/parts/gear.lua, a prism of 1 200 points with a keyed bore), the
# turned vase (a lathe of 200 points), a lattice of 400 tori on a plane
# (bench/parts/torus_lattice.lua), 200 lens parts of balls, a cylinder and
# an ellipsoid (lens_field.lua), glass and a mirror to depth 8
# (glass.lua), the Sierpinski tetrahedron of level 6 (sierpinski.lua,
# a mesh in POV-Ray) and a chart of 64 superellipsoids
# (superellipsoids.lua) at 1024x768 on one core, whole
# process, against their twins in bench/povray/, alternating PAIRS times;
# medians compared. POV-Ray's prism cannot twist, so the gear is compared
# untwisted; the twisted one (30°) is timed beside it, on its own. The
# last column: the share of pixels whose colour differs from POV-Ray's by
# more than 0.02 (five levels of 255) in a channel (OpenImageIO's idiff),
# where shading conventions differ (ambient, highlights, gamma), not
# geometry: look at the two images side by side in the output folder.
# The rays csgray traced a second (camera, shadow and secondary rays, from
# --stats, median of its runs), and that as a share of 20 M/s, about what
# a single-ray tracer of analytic shapes at the state of the art does on
# one core.
if command -v povray >/dev/null; then
  echo
  echo "| render vs POV-Ray | csgray median (s) | POV-Ray median (s) | POV-Ray / csgray | pixels off by > 0.02 | csgray rays/s | of 20 M/s |"
  echo "|---|---:|---:|---:|---:|---:|---:|"
  for row in gear:bench/parts/gear.lua:twist=0 turned_vase:bench/parts/turned_vase.lua: \
    torus_lattice:bench/parts/torus_lattice.lua: lens_field:bench/parts/lens_field.lua: \
    glass:bench/parts/glass.lua: sierpinski:bench/parts/sierpinski.lua: \
    superellipsoids:bench/parts/superellipsoids.lua:; do
    IFS=: read -r name script define <<<"$row"
    defines=()
    [ -n "$define" ] && defines=(-D "$define")
    : >"$out/a"; : >"$out/b"; : >"$out/rays"
    for ((r = 0; r < pairs; r++)); do
      time_of $one_core "$csgray" render "$script" "${defines[@]}" -o "$out/$name.png" \
        --size 1024x768 --threads 1 --stats >>"$out/a"
      sed -n 's/.*; \([0-9.]*\) M rays\/s in all/\1/p' "$out/err" >>"$out/rays"
      time_of $one_core povray +I"bench/povray/$name.pov" +O"$out/${name}_pov.png" +W1024 +H768 \
        -D +WT1 -GA >>"$out/b"
    done
    a=$(grep -v failed "$out/a" | median); b=$(grep -v failed "$out/b" | median)
    off=-
    command -v idiff >/dev/null &&
      off=$({ idiff -fail 0.02 "$out/$name.png" "$out/${name}_pov.png" 2>/dev/null || true; } |
        awk '/over 0.02/ {gsub(/[()]/, "", $3); print $3; exit}')
    rays=$(median <"$out/rays")
    printf '| %s | %s | %s | %s | %s | %s | %s |\n' "$name" "${a:--}" "${b:--}" \
      "$(awk -v a="$a" -v b="$b" 'BEGIN {if (a == "" || b == "") print "-"; else printf "%.1f", b / a}')" \
      "${off:--}" "${rays:+$rays M}" \
      "$(awk -v r="$rays" 'BEGIN {if (r == "") print "-"; else printf "%.0f %%", r / 20 * 100}')"
  done
  : >"$out/a"
  for ((r = 0; r < pairs; r++)); do
    time_of $one_core "$csgray" render bench/parts/gear.lua -o "$out/gear.png" --size 1024x768 \
      --threads 1 >>"$out/a"
  done
  echo
  echo "gear twisted by 30°, csgray alone: median $(grep -v failed "$out/a" | median) s"
else
  echo
  echo "(render vs POV-Ray left out: make bench installs povray)"
fi

# csgray view (bench/view_bench.mjs): frames per second while orbiting at
# 800x600 on two threads, asked over HTTP as the page asks (one frame at a
# time), for each of the page's three passes; the frames the page itself
# draws during a drag in chromium (when the browser test's puppeteer-core
# and chromium are installed); and the time from a save of the script to
# its first pass (median of 7; 0.1 s of it is the watcher's debounce).
if command -v node >/dev/null; then
  echo
  echo "| view: orbit at 800x600, 2 threads | primitives | pass 0, 200x150 (frames/s) | pass 1, 800x600 (frames/s) | pass 2, antialiased (frames/s) | drag in chromium (frames/s; moves/s) | save to first pass (ms) |"
  echo "|---|---:|---:|---:|---:|---:|---:|"
  for row in bench/plate.lua:n=8 bench/plate.lua:n=16 examples/showcase.lua: examples/bracket.lua:; do
    IFS=: read -r script define <<<"$row"
    node bench/view_bench.mjs "$csgray" "$script" $define || echo "| $script $define | failed |"
  done
else
  echo
  echo "(csgray view left out: it needs node)"
fi

# csgray view against OpenSCAD's preview (installed by `make bench` with
# xvfb, which gives it a display): plate(8) (bench/view/plate8.scad, the
# same part) from the same eye and centre at 800x600, with OpenSCAD's view
# angle (22.5° vertically, -D fov=29.6 horizontally for csgray), whole
# process each, alternating PAIRS times on two threads; medians. csgray's
# first frame is the page's first pass (a quarter of the size each way,
# one ray a pixel), its full frame the last (full size, 4 rays a pixel at
# edges).
if command -v openscad >/dev/null && command -v xvfb-run >/dev/null; then
  echo
  echo "| plate(8), 800x600 | median (s) |"
  echo "|---|---:|"
  : >"$out/a"; : >"$out/b"; : >"$out/c"; : >"$out/d"
  for ((r = 0; r < pairs; r++)); do
    # (time_of prints no newline.)
    echo "$(time_of xvfb-run -a openscad --preview -o "$out/openscad.png" --imgsize 800,600 \
      --camera=50,-90,110,50,50,0 --projection=p bench/view/plate8.scad)" >>"$out/a"
    echo "$(time_of "$csgray" render bench/plate.lua -D fov=29.6 -o "$out/first.png" \
      --size 200x150 --threads 2)" >>"$out/b"
    echo "$(time_of "$csgray" render bench/plate.lua -D fov=29.6 -o "$out/full.png" \
      --size 800x600 --samples 4 --adaptive --threads 2)" >>"$out/c"
    echo "$(time_of xvfb-run -a true)" >>"$out/d"
  done
  echo "| OpenSCAD --preview under xvfb-run | $(grep -v failed "$out/a" | median) |"
  echo "| xvfb-run alone (its share of the above) | $(grep -v failed "$out/d" | median) |"
  echo "| csgray, first frame (200x150) | $(grep -v failed "$out/b" | median) |"
  echo "| csgray, full frame (800x600, antialiased) | $(grep -v failed "$out/c" | median) |"
else
  echo
  echo "(view vs OpenSCAD left out: make bench installs openscad and xvfb)"
fi
