#!/usr/bin/env bash
# The csgray command line: good input works; bad input gets one line on
# stderr, a non-zero exit, and leaves no output file (and an old one as it was).
set -u
csgray=$1
source_dir=$2
version=$3  # what --version should print: "0.1.0 (x86-64-v3)" or "0.1.0 (portable)"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0
failed=0

pass() { passed=$((passed + 1)); }
fail() { failed=$((failed + 1)); echo "FAIL: $*"; }

printf 'return box{size={10, 20, 5}} - sphere{r=4}:translate(5, 10, 5)\n' > "$work/part.lua"
printf 'local r = radius or 1\nreturn sphere{r=r}\n' > "$work/param.lua"
printf 'local a = box(1)\nlocal b = sphere{r=-2}\nreturn a - b\n' > "$work/bad.lua"
printf 'return box(1):scale(0, 1, 1)\n' > "$work/singular.lua"
printf 'while true do end\n' > "$work/loop.lua"
printf 'return box(1) +\n' > "$work/syntax.lua"
printf 'error({})\n' > "$work/table_error.lua"
printf 'error("first\\nsecond")\n' > "$work/multiline.lua"
printf 'error("\\27[2J\\27[31mred")\n' > "$work/escape.lua"
printf 'error("before\\0after")\n' > "$work/nul.lua"
printf 'return half_space{normal={0, 0, 1}}\n' > "$work/unbounded.lua"
# Backtracking in C, where no Lua instruction is counted: only the
# script time limit ends it.
printf 'local s = string.rep("a", 200000)\nlocal found = s:find(".-.-.-.-b")\nreturn sphere(1)\n' > "$work/pattern.lua"

# expect_exit CODE NAME OUTPUT-FILE-OR-"" ARGS...: exit with CODE ("any"
# for any failure that is not a crash), exactly one line on stderr that
# starts with "csgray: error:", and no output file.
expect_exit() {
  local want=$1 name=$2 output=$3
  shift 3
  "$csgray" "$@" >"$work/stdout" 2>"$work/stderr"
  local code=$?
  local lines
  lines=$(wc -l <"$work/stderr")
  if [ $code -eq 0 ]; then
    fail "$name: exit code 0"
  elif [ $code -ge 128 ]; then
    fail "$name: crashed with exit code $code"
  elif [ "$want" != any ] && [ $code -ne "$want" ]; then
    fail "$name: exit code $code, expected $want"; cat "$work/stderr"
  elif [ "$lines" -ne 1 ] || ! grep -q '^csgray: error: ' "$work/stderr"; then
    fail "$name: stderr is not one 'csgray: error:' line:"; cat "$work/stderr"
  elif [ -n "$output" ] && [ -e "$output" ]; then
    fail "$name: left $output behind"
  else
    pass
  fi
}

expect_failure() { expect_exit any "$@"; }

expect_in_stderr() {
  if grep -qF -- "$2" "$work/stderr"; then pass; else fail "$1: stderr lacks '$2':"; cat "$work/stderr"; fi
}

# --version names the instruction set the build was configured for.
if [ "$("$csgray" --version 2>&1)" = "$version" ]; then pass; else
  fail "--version printed '$("$csgray" --version 2>&1)', expected '$version'"
fi

# A good render writes the image and says so.
if "$csgray" render "$work/part.lua" -o "$work/part.png" --size 64x48 --threads 2 >"$work/stdout" 2>&1 &&
   [ -s "$work/part.png" ] && grep -q "wrote $work/part.png (64x48)" "$work/stdout"; then
  pass
else
  fail "good render"; cat "$work/stdout"
fi

# An empty difference: info says no ray meets it, render has nothing to
# frame (it wrote a blank image).
printf 'return box(10) - box(10)\n' > "$work/empty.lua"
if "$csgray" info "$work/empty.lua" >"$work/stdout" 2>&1 &&
   grep -q 'bounds: *empty (no ray through \[0, 0, 0\] \.\. \[10, 10, 10\] meets the part)' "$work/stdout"; then
  pass
else
  fail "info of an empty part"; cat "$work/stdout"
fi
expect_exit 1 "render of an empty part" "$work/empty.png" render "$work/empty.lua" -o "$work/empty.png"
expect_in_stderr "render of an empty part" "empty.lua: nothing to frame: the part is empty"

# info prints the part's bounds: a ghost is no part of it.
printf 'return union{box(10), sphere(5):translate(30, 0, 0):ghost()}\n' > "$work/ghost.lua"
if "$csgray" info "$work/ghost.lua" >"$work/stdout" 2>&1 &&
   grep -q 'bounds: *\[0, 0, 0\] \.\. \[10, 10, 10\]' "$work/stdout"; then
  pass
else
  fail "info with a ghost"; cat "$work/stdout"
fi

# info prints the bounds and the tree.
if "$csgray" info "$work/part.lua" >"$work/stdout" 2>&1 &&
   grep -q 'bounds: *\[0, 0, 0\] \.\. \[10, 20, 5\]' "$work/stdout" &&
   grep -q 'primitives: *2' "$work/stdout" && grep -q 'boolean nodes: *1' "$work/stdout"; then
  pass
else
  fail "info"; cat "$work/stdout"
fi

# A moved union is stored once: info counts its uses and what is stored.
cat >"$work/instances.lua" <<'EOF2'
local pair = union(sphere{r=1}, sphere{r=1}:translate(1.5, 0, 0))
return union(pair, pair:translate(0, 5, 0), pair:translate(0, 10, 0))
EOF2
if "$csgray" info "$work/instances.lua" >"$work/stdout" 2>&1 &&
   grep -q 'primitives: *6 (2 distinct, the rest placed again by instances)' "$work/stdout"; then
  pass
else
  fail "info with instances"; cat "$work/stdout"
fi

# info names a lens's blur (it multiplies the rays) and the fog.
cat >"$work/lens.lua" <<'EOF2'
return scene{objects = sphere(1), camera = camera{eye = {0, -5, 0}, aperture = 0.5, blur_samples = 25},
             fog = {color = {1, 1, 1}, distance = 9, offset = 1, altitude = 2}}
EOF2
if "$csgray" info "$work/lens.lua" >"$work/stdout" 2>&1 &&
   grep -q 'camera: *set (focal blur: aperture 0.5, at least 25 rays a pixel)' "$work/stdout" &&
   grep -q 'fog: *distance 9, ground fog up to z = 1, thinning over 2' "$work/stdout"; then
  pass
else
  fail "info of a lens and fog"; cat "$work/stdout"
fi

# info names bumps (they cost a render several times) and a sky: the two
# bumped balls and the plane, not the plain box.
cat >"$work/bumped.lua" <<'EOF2'
local rough = sphere(1):material{bumps = perlin{scale = 0.2}, bump_depth = 0.05}
return scene{objects = {union(rough, rough:translate(3, 0, 0)), box(1):translate(0, 3, 0),
                        plane{}:material{bumps = checker{size = 1}}},
             background = gradient{colors = {{1, 1, 1}, {0, 0, 1}}}}
EOF2
if "$csgray" info "$work/bumped.lua" >"$work/stdout" 2>&1 &&
   grep -q 'bumps: *on 3 primitives and surfaces' "$work/stdout" &&
   grep -q 'background: *a texture by direction (a sky)' "$work/stdout" &&
   "$csgray" info "$work/lens.lua" >"$work/stdout" 2>&1 && ! grep -q 'bumps\|background' "$work/stdout"; then
  pass
else
  fail "info of bumps and a sky"; cat "$work/stdout"
fi

# -D sets a global.
if "$csgray" info "$work/param.lua" -D radius=3 >"$work/stdout" 2>&1 &&
   grep -q '\[3, 3, 3\]' "$work/stdout"; then
  pass
else
  fail "-D"; cat "$work/stdout"
fi

expect_failure "script error" "$work/out.png" render "$work/bad.lua" -o "$work/out.png"
expect_in_stderr "script error" "bad.lua:2: sphere: r must be > 0 (got -2)"
expect_failure "singular transform" "$work/out.png" render "$work/singular.lua" -o "$work/out.png"
expect_in_stderr "singular transform" "singular.lua:1: transform is singular"
expect_failure "syntax error" "$work/out.png" render "$work/syntax.lua" -o "$work/out.png"
expect_in_stderr "syntax error" "syntax.lua:"
expect_failure "endless loop" "$work/out.png" render "$work/loop.lua" -o "$work/out.png"
expect_in_stderr "endless loop" "instruction budget"
expect_failure "slow C call" "$work/out.png" render "$work/pattern.lua" -o "$work/out.png" --script-timeout 0.5
expect_in_stderr "slow C call" "pattern.lua: the script did not finish within 0.5 s (--script-timeout)"
expect_failure "negative timeout" "$work/out.png" render "$work/part.lua" -o "$work/out.png" --script-timeout -1
expect_failure "table error" "$work/out.png" render "$work/table_error.lua" -o "$work/out.png"
expect_in_stderr "table error" "table_error.lua:1: error(table) without a message"
expect_failure "multi-line error" "$work/out.png" render "$work/multiline.lua" -o "$work/out.png"
expect_in_stderr "multi-line error" "multiline.lua:1: first second"
# An escape sequence in a script's error cannot clear the terminal.
expect_failure "escape in an error" "$work/out.png" render "$work/escape.lua" -o "$work/out.png"
expect_in_stderr "escape in an error" "escape.lua:1: ?[2J?[31mred"
expect_failure "NUL in an error" "$work/out.png" render "$work/nul.lua" -o "$work/out.png"
expect_in_stderr "NUL in an error" "nul.lua:1: before?after"
expect_failure "unbounded without camera" "$work/out.png" render "$work/unbounded.lua" -o "$work/out.png"
expect_in_stderr "unbounded without camera" "unbounded.lua: cannot frame an unbounded solid"
# OpenSCAD's source is not run as Lua: the message says how to make a .csg.
echo 'cube(10);' > "$work/part.scad"
expect_failure "scad source" "$work/out.stl" export "$work/part.scad" -o "$work/out.stl"
expect_in_stderr "scad source" "part.scad: csgray reads OpenSCAD's .csg files, not its .scad source: export one with openscad -o part.csg part.scad"
# A plane alone has no size either; it is not an empty solid.
echo 'return plane{}' > "$work/plane_only.lua"
expect_failure "plane without camera" "$work/out.png" render "$work/plane_only.lua" -o "$work/out.png"
expect_in_stderr "plane without camera" "plane_only.lua: cannot frame an unbounded surface such as a plane"
expect_failure "NaN timeout" "$work/out.png" render "$work/part.lua" -o "$work/out.png" --script-timeout nan
expect_failure "huge timeout" "$work/out.png" render "$work/part.lua" -o "$work/out.png" --script-timeout 1e10
# A word is refused in csgray's words, as a number out of range is.
expect_exit 2 "word for a timeout" "$work/out.png" render "$work/part.lua" -o "$work/out.png" --timeout abc
expect_in_stderr "word for a timeout" "--timeout: must be a number from 0 to 1e6 (seconds; 0: no limit)"
expect_failure "output is a folder" "" render "$work/part.lua" -o "$work"
mkdir -p "$work/dir.png"
expect_failure "output is a folder named like an image" "" render "$work/part.lua" -o "$work/dir.png"
cp "$work/part.lua" "$work/copy.lua"
expect_failure "output is the script" "" render "$work/copy.lua" -o "$work/copy.lua"
if cmp -s "$work/part.lua" "$work/copy.lua"; then pass; else fail "the script was overwritten"; fi
expect_failure "script is a folder" "$work/out.png" render "$work" -o "$work/out.png"
expect_in_stderr "script is a folder" "is a folder, not a script"
expect_failure "endless script file" "$work/out.png" info /dev/zero
expect_in_stderr "endless script file" "/dev/zero: script is larger than 16 MiB"
expect_failure "define overflows" "$work/out.png" render "$work/param.lua" -o "$work/out.png" -D radius=1e999
expect_failure "define shadows the API" "$work/out.png" render "$work/param.lua" -o "$work/out.png" -D sphere=3
expect_in_stderr "define shadows the API" "'sphere' is a built-in name"
expect_failure "define is a keyword" "$work/out.png" render "$work/param.lua" -o "$work/out.png" -D end=3
printf '#!/usr/bin/env csgray\nreturn sphere(1)\n' > "$work/shebang.lua"
printf '\xef\xbb\xbf#!/usr/bin/env csgray\nreturn sphere{r=-1}\n' > "$work/bom.lua"
if "$csgray" info "$work/shebang.lua" >/dev/null 2>&1; then pass; else fail "a #! first line is refused"; fi
expect_failure "BOM and shebang keep line numbers" "" info "$work/bom.lua"
expect_in_stderr "BOM and shebang keep line numbers" "bom.lua:2: sphere: r must be > 0"
expect_failure "missing script" "$work/out.png" render "$work/nope.lua" -o "$work/out.png"
expect_in_stderr "missing script" "nope.lua: cannot open script"
expect_failure "unknown option" "$work/out.png" render "$work/part.lua" -o "$work/out.png" --frobnicate
expect_failure "no subcommand" ""
expect_failure "missing output" "" render "$work/part.lua"
expect_failure "zero size" "$work/out.png" render "$work/part.lua" -o "$work/out.png" --size 0x10
expect_failure "absurd size" "$work/out.png" render "$work/part.lua" -o "$work/out.png" --size 100000x100000
expect_failure "too many pixels" "$work/out.png" render "$work/part.lua" -o "$work/out.png" --size 16000x16000
expect_failure "malformed size" "$work/out.png" render "$work/part.lua" -o "$work/out.png" --size big
# An option given twice, in words.
expect_exit 2 "output given twice" "$work/out.png" render "$work/part.lua" -o "$work/out.png" -o "$work/out2.png"
expect_in_stderr "output given twice" "--output: given 2 times; give it once"
# A side of many digits is a size out of range, not a malformed one.
expect_exit 2 "size of many digits" "$work/out.png" render "$work/part.lua" -o "$work/out.png" --size 1x67108864
expect_in_stderr "size of many digits" "--size: image size 1x67108864 is out of range"
expect_failure "negative threads" "$work/out.png" render "$work/part.lua" -o "$work/out.png" --threads -1
expect_failure "unknown format" "$work/out.xyz" render "$work/part.lua" -o "$work/out.xyz"
expect_in_stderr "unknown format" "unknown image format '.xyz'"
# OpenImageIO's terminal and null writers make no file: not image formats.
for ext in term null; do
  expect_failure "$ext format" "$work/out.$ext" render "$work/part.lua" -o "$work/out.$ext" --size 8x6
  expect_in_stderr "$ext format" "unknown image format '.$ext'"
  if [ -s "$work/stdout" ]; then fail "$ext format: wrote to stdout"; else pass; fi
done
expect_failure "no extension" "$work/out" render "$work/part.lua" -o "$work/out"
expect_failure "missing folder" "$work/no/such/out.png" render "$work/part.lua" -o "$work/no/such/out.png"
expect_in_stderr "missing folder" "cannot write $work/no/such/out.png: folder $work/no/such does not exist"
expect_failure "bad define" "$work/out.png" render "$work/part.lua" -o "$work/out.png" -D novalue

# A failed render leaves an existing image untouched.
echo "old image" > "$work/keep.png"
expect_failure "keep old file" "" render "$work/bad.lua" -o "$work/keep.png"
if [ "$(cat "$work/keep.png")" = "old image" ]; then pass; else fail "old file was clobbered"; fi

# A folder that cannot be written: the error names the file, nothing is left.
# A read-only folder: chmod for a user; root ignores modes, so as root the
# folder is made immutable (chattr +i, which root cannot write past either).
mkdir "$work/readonly" && printf 'old' > "$work/readonly/part.stl"
if [ "$(id -u)" != 0 ]; then
  chmod 555 "$work/readonly"
else
  chattr +i "$work/readonly"
fi
if touch "$work/readonly/probe" 2>/dev/null; then
  fail "read-only folder: could not make $work/readonly read-only"
  rm -f "$work/readonly/probe"
else
  expect_failure "read-only folder" "$work/readonly/out.png" render "$work/part.lua" -o "$work/readonly/out.png"
  expect_exit 1 "export into a read-only folder" "" export "$work/part.lua" -o "$work/readonly/part.stl"
  if [ "$(cat "$work/readonly/part.stl")" = old ] && [ "$(ls -A "$work/readonly")" = part.stl ]; then
    pass
  else
    fail "export into a read-only folder changed the old file or left a temporary"
  fi
fi
chattr -i "$work/readonly" 2>/dev/null
chmod 755 "$work/readonly"

# No temporary files are left anywhere in the work folder.
if ls -A "$work" | grep -q '\.tmp'; then fail "temporary files left: $(ls -A "$work")"; else pass; fi

# The showcase renders from the command line.
if "$csgray" render "$source_dir/examples/showcase.lua" -o "$work/showcase.png" --size 80x60 >/dev/null 2>&1 &&
   [ -s "$work/showcase.png" ]; then pass; else fail "showcase"; fi

# expect_exit CODE NAME OUTPUT-FILE-OR-"" ARGS...: as expect_failure, and the
# exit code must be CODE (1: the script, scene or output failed; 2: the
# command line is wrong).

# Width and height of a PNG from its IHDR chunk, as "WxH".
png_size() {
  local b
  read -r -a b < <(od -An -v -tu1 -j16 -N8 "$1")
  echo "$(((b[0] << 24) | (b[1] << 16) | (b[2] << 8) | b[3]))x$(((b[4] << 24) | (b[5] << 16) | (b[6] << 8) | b[7]))"
}
is_png() { [ "$(od -An -tx1 -N8 "$1" | tr -d ' \n')" = 89504e470d0a1a0a ]; }

# The pixel types of the channels of an EXR file (its "channels" attribute),
# as little-endian hex words: 02000000 is FLOAT, 01000000 HALF, 00000000 UINT.
exr_pixel_types() {
  local hex rest types=""
  hex=$(head -c 4096 "$1" | od -An -v -tx1 | tr -d ' \n')
  rest=${hex#*6368616e6e656c730063686c69737400}  # "channels\0chlist\0"
  [ "$rest" != "$hex" ] || return 1
  rest=${rest:8}  # the attribute's size
  # Each channel: its name, \0, the pixel type (4 bytes), pLinear and 3
  # reserved bytes, x and y sampling (4 bytes each); a \0 ends the list.
  while [ -n "$rest" ] && [ "${rest:0:2}" != 00 ]; do
    while [ -n "$rest" ] && [ "${rest:0:2}" != 00 ]; do rest=${rest:2}; done
    types="$types ${rest:2:8}"
    rest=${rest:34}
  done
  echo "${types# }"
}

csgray_abs=$(cd "$(dirname "$csgray")" && pwd)/$(basename "$csgray")
source_abs=$(cd "$source_dir" && pwd)

# --samples is 1 to 1024; --adaptive needs samples to spend; --aov knows
# depth and normal. A wrong command line is exit code 2.
expect_exit 2 "zero samples" "$work/out.png" render "$work/part.lua" -o "$work/out.png" --samples 0
expect_exit 2 "too many samples" "$work/out.png" render "$work/part.lua" -o "$work/out.png" --samples 2000
# A scene{} gets one sample by default; a bare solid gets the CAD look's
# adaptive samples, so --adaptive alone is enough for it.
printf 'return scene{objects={box(1)}}\n' > "$work/scene_part.lua"
expect_exit 2 "adaptive without samples" "$work/out.png" render "$work/scene_part.lua" -o "$work/out.png" --adaptive
expect_in_stderr "adaptive without samples" "--samples"
if "$csgray" render "$work/part.lua" -o "$work/bare_adaptive.png" --size 32x24 --adaptive --edges \
     >/dev/null 2>"$work/stderr" && [ "$(png_size "$work/bare_adaptive.png")" = 32x24 ]; then
  pass
else
  fail "a bare solid with --adaptive --edges"; cat "$work/stderr"
fi
expect_exit 2 "adaptive with one sample" "$work/out.png" render "$work/part.lua" -o "$work/out.png" --adaptive --samples 1
expect_exit 2 "unknown aov" "$work/out.png" render "$work/part.lua" -o "$work/out.png" --aov foo
expect_exit 2 "unknown aov in a list" "$work/out.png" render "$work/part.lua" -o "$work/out.png" --aov depth,foo
if [ -e "$work/out.depth.png" ] || [ -e "$work/out.normal.png" ]; then fail "a refused --aov left files"; else pass; fi
# The bounds are allowed, and adaptive sampling renders.
if "$csgray" render "$work/part.lua" -o "$work/samples.png" --size 16x12 --samples 1024 >/dev/null 2>&1 &&
   [ -s "$work/samples.png" ]; then pass; else fail "--samples 1024"; fi
if "$csgray" render "$work/part.lua" -o "$work/adaptive.png" --size 32x24 --samples 4 --adaptive \
     >/dev/null 2>"$work/stderr" && [ "$(png_size "$work/adaptive.png")" = 32x24 ]; then
  pass
else
  fail "--adaptive --samples 4"; cat "$work/stderr"
fi

# --aov depth,normal writes NAME.depth.EXT and NAME.normal.EXT beside NAME.EXT.
mkdir "$work/aov"
if "$csgray" render "$work/part.lua" -o "$work/aov/part.png" --size 32x24 --aov depth,normal \
     >"$work/stdout" 2>"$work/stderr"; then
  for f in part.png part.depth.png part.normal.png; do
    if is_png "$work/aov/$f" && [ "$(png_size "$work/aov/$f")" = 32x24 ]; then
      pass
    else
      fail "--aov: $f is not a 32x24 PNG"
    fi
  done
  if [ "$(ls -A "$work/aov" | wc -l)" -eq 3 ]; then pass; else fail "--aov wrote: $(ls -A "$work/aov")"; fi
else
  fail "--aov depth,normal"; cat "$work/stderr"
fi
# An 8-bit normal image holds (n + 1) / 2: a floor seen from above, its
# normal (0, 0, 1), is 128 128 255 in every pixel (a component of 0 was
# written as 0, as if nothing had been hit).
cat >"$work/floor.lua" <<'LUA'
return scene{objects={plane{}}, camera=camera{eye={0, 0, 10}, look_at={0, 0, 0}, up={0, 1, 0}}}
LUA
mkdir "$work/aovn"
if "$csgray" render "$work/floor.lua" -o "$work/aovn/floor.ppm" --size 4x3 --aov normal \
     >/dev/null 2>"$work/stderr" &&
   [ "$(tail -c 36 "$work/aovn/floor.normal.ppm" | od -An -tu1 | tr -s ' \n' ' ')" = \
     " $(for i in 1 2 3 4 5 6 7 8 9 10 11 12; do printf '128 128 255 '; done)" ]; then
  pass
else
  fail "--aov normal: a floor's 8-bit normals are not 128 128 255"; cat "$work/stderr"
fi
# One of them only; the plain render at the top wrote none.
mkdir "$work/aov1"
"$csgray" render "$work/part.lua" -o "$work/aov1/part.png" --size 16x12 --aov normal >/dev/null 2>&1
if [ "$(ls "$work/aov1" | tr '\n' ' ')" = "part.normal.png part.png " ]; then
  pass
else
  fail "--aov normal wrote: $(ls "$work/aov1" | tr '\n' ' ')"
fi
if [ -e "$work/part.depth.png" ] || [ -e "$work/part.normal.png" ]; then
  fail "a render without --aov wrote AOV images"
else
  pass
fi
# Past a file-size limit (ulimit -f) every image stays as it was, when the
# last one written fails: the limit lets the depth and normal images
# through and stops the colour image, which is the largest here. A
# one-line error, exit 1, no temporary file left (the limit's signal
# would end the process mid-write).
mkdir "$work/limit"
"$csgray" render "$source_dir/examples/torus.lua" -o "$work/limit/free.png" --size 200x150 \
  --aov depth,normal >/dev/null 2>&1
largest_aov=$(stat -c %s "$work/limit/free.depth.png" "$work/limit/free.normal.png" | sort -n | tail -1)
colour=$(stat -c %s "$work/limit/free.png")
limit_kib=$(((largest_aov + 1023) / 1024))
if [ $((limit_kib * 1024)) -lt "$colour" ]; then pass; else fail "the colour image is not the largest"; fi
for f in out out.depth out.normal; do echo old > "$work/limit/$f.png"; done
(ulimit -f "$limit_kib"
 "$csgray" render "$source_dir/examples/torus.lua" -o "$work/limit/out.png" --size 200x150 \
   --aov depth,normal >"$work/stdout" 2>"$work/stderr"
 echo $? > "$work/limit/code")
if [ "$(cat "$work/limit/code")" = 1 ] && [ "$(wc -l <"$work/stderr")" = 1 ] &&
   grep -q "^csgray: error: cannot write $work/limit/out.png" "$work/stderr"; then
  pass
else
  fail "render past a file-size limit: exit $(cat "$work/limit/code")"; cat "$work/stderr"
fi
for f in out out.depth out.normal; do
  if [ "$(cat "$work/limit/$f.png")" = old ]; then pass; else fail "$f.png was replaced"; fi
done
if [ "$(ls -A "$work/limit" | grep -vc '^free\|^out\|^code$')" = 0 ]; then
  pass
else
  fail "temporaries left: $(ls -A "$work/limit")"
fi
# EXR keeps floating point: every channel of the depth image is FLOAT.
mkdir "$work/exr"
if "$csgray" render "$work/part.lua" -o "$work/exr/part.exr" --size 16x12 --aov depth,normal >/dev/null 2>&1 &&
   [ -s "$work/exr/part.exr" ] && [ -s "$work/exr/part.normal.exr" ] &&
   [ "$(exr_pixel_types "$work/exr/part.depth.exr")" = "02000000 02000000 02000000" ]; then
  pass
else
  fail "--aov with .exr: depth channels are '$(exr_pixel_types "$work/exr/part.depth.exr" 2>&1)'; files: $(ls "$work/exr")"
fi
# A failing script with --aov leaves no file at all.
mkdir "$work/aovfail"
expect_exit 1 "failing script with --aov" "$work/aovfail/out.png" render "$work/bad.lua" \
  -o "$work/aovfail/out.png" --aov depth,normal
if [ -z "$(ls -A "$work/aovfail")" ]; then pass; else fail "failing --aov render left: $(ls -A "$work/aovfail")"; fi

# Standard error is not a terminal here: a render that takes over a second
# (when the bar would show) prints no progress bar; stderr stays empty.
printf '%s\n' 'return scene{' \
  '  objects = {sphere{r=1}:material{reflection=0.5}, plane{}:material{color=marble{}}},' \
  '  camera = camera{eye={0, -5, 2}, look_at={0, 0, 0}},' \
  '  lights = {sphere_light{pos={2, -2, 5}, r=1, samples=1024}},' \
  '}' > "$work/slow.lua"
if "$csgray" render "$work/slow.lua" -o "$work/slow.png" --size 64x48 --threads 1 --samples 12 \
     >"$work/stdout" 2>"$work/stderr" && [ -s "$work/slow.png" ]; then
  if [ -s "$work/stderr" ]; then fail "progress written to a pipe:"; od -c "$work/stderr" | head -5; else pass; fi
  seconds=$(sed -n 's/.* in \([0-9.]*\) s$/\1/p' "$work/stdout")
  case "$seconds" in 0.*) echo "note: the progress check rendered in $seconds s, under the bar's 1 s";; esac
else
  fail "slow render"; cat "$work/stderr"
fi

# The same render on a terminal (a pty from script(1), util-linux) shows the
# bar once the first second has passed, and clears it at the end.
if command -v script >/dev/null; then
  script -qec "'$csgray' render '$work/slow.lua' -o '$work/slow.png' --size 64x48 --threads 1 --samples 12" \
    /dev/null >"$work/tty" 2>&1
  # This run's own time decides (a loaded machine makes the first run slow
  # and this one fast, or the other way round).
  seconds=$(tr '\r' '\n' <"$work/tty" | sed -n 's/.* in \([0-9.]*\) s$/\1/p' | tail -1)
  case "$seconds" in
    0.*|'') echo "note: the render took ${seconds:-?} s, under the bar's 1 s: the terminal check is skipped";;
    *) if grep -q "rendering \[#*\.*\] *[0-9]*%" "$work/tty"; then pass; else fail "no progress bar on a terminal"; od -c "$work/tty" | head -5; fi;;
  esac
fi

# image_texture: a missing file is exit 1 and one line naming it; a file
# outside the script's folder is refused.
printf 'local a = box(1)\nreturn a:material{color=image_texture{file="nope.png"}}\n' > "$work/tex_missing.lua"
expect_exit 1 "missing texture image" "$work/out.png" render "$work/tex_missing.lua" -o "$work/out.png"
expect_in_stderr "missing texture image" "tex_missing.lua:2: "
expect_in_stderr "missing texture image" "nope.png"
mkdir "$work/scripts"
printf 'return box(1):material{color=image_texture{file="../part.png"}}\n' > "$work/scripts/escape.lua"
expect_exit 1 "texture outside the folder" "$work/out.png" render "$work/scripts/escape.lua" -o "$work/out.png"
expect_in_stderr "texture outside the folder" "escape.lua:1: image_texture: file ../part.png is outside the script's folder"

# Texture files are relative to the script, not to the working directory.
if (cd "$work" && "$csgray_abs" render "$source_abs/examples/textured_box.lua" -o textured.png --size 40x30 \
      >/dev/null 2>"$work/stderr") && [ -s "$work/textured.png" ]; then
  pass
else
  fail "textured_box.lua from another folder"; cat "$work/stderr"
fi
if (cd "$source_abs/examples/textures" && "$csgray_abs" render ../textured_box.lua -o "$work/textured2.png" \
      --size 40x30 >/dev/null 2>"$work/stderr") && [ -s "$work/textured2.png" ]; then
  pass
else
  fail "textured_box.lua by a relative path from a subfolder"; cat "$work/stderr"
fi

# --samples is read as decimal digits only (CLI11 would read 0x10 as 16).
expect_exit 2 "hexadecimal samples" "$work/hex.png" render "$work/part.lua" -o "$work/hex.png" --samples 0x10
# An AOV file named after the output may not be the script either.
cp "$work/part.lua" "$work/s.depth.png"
expect_failure "AOV over the script" "" render "$work/s.depth.png" -o "$work/s.png" --aov depth --size 40x30
if cmp -s "$work/part.lua" "$work/s.depth.png" && [ ! -e "$work/s.png" ]; then pass; else fail "AOV over the script changed it"; fi

# ---- export ------------------------------------------------------------------
# A good export writes the mesh and says so, in every format.
for ext in stl obj off ply 3mf; do
  if "$csgray" export "$work/part.lua" -o "$work/part.$ext" >"$work/stdout" 2>"$work/stderr" &&
     [ -s "$work/part.$ext" ] && grep -q "wrote $work/part.$ext (" "$work/stdout" && [ ! -s "$work/stderr" ]; then
    pass
  else
    fail "good export to .$ext"; cat "$work/stdout" "$work/stderr"
  fi
done
# The same part gives the same file every time (the rounded box's
# booleans once came back in an order that varied from run to run, and the
# repair after rounding then moved different points).
for run in 1 2 3 4 5; do
  "$csgray" export "$source_dir/examples/rounded_box.lua" -o "$work/same$run.obj" >/dev/null 2>&1
done
if [ -s "$work/same1.obj" ] && cmp -s "$work/same1.obj" "$work/same2.obj" &&
  cmp -s "$work/same1.obj" "$work/same3.obj" && cmp -s "$work/same1.obj" "$work/same4.obj" &&
  cmp -s "$work/same1.obj" "$work/same5.obj"; then pass; else fail "the same part exported twice differs"; fi

# Bad exports: one line, exit 1 (2 for the command line), no file.
expect_failure "export of an unknown format" "$work/part.xyz" export "$work/part.lua" -o "$work/part.xyz"
expect_in_stderr "export of an unknown format" "unknown mesh format '.xyz'"
expect_in_stderr "export of an unknown format" "; .svg or .dxf for a 2D outline)"
expect_failure "export into a folder" "" export "$work/part.lua" -o "$work"
expect_in_stderr "export into a folder" "cannot write $work: it is a folder"
expect_failure "export of an unbounded part" "$work/unbounded.stl" export "$work/unbounded.lua" -o "$work/unbounded.stl"
expect_in_stderr "export of an unbounded part" "unbounded.lua: the part is unbounded"
# Boxes that share only an edge are joined (docs/cli.md, "Contacts"); of
# different heights, so that they are not one extrusion of their outlines.
printf 'return box(1) + box{size={1, 1, 2}}:translate(1, 1, 0)\n' > "$work/edge.lua"
if "$csgray" export "$work/edge.lua" -o "$work/edge.stl" --stats >"$work/stdout" 2>"$work/stderr" &&
   [ -s "$work/edge.stl" ] && grep -q '1 contact resolved' "$work/stderr"; then
  pass
else
  fail "export of boxes that share an edge"; cat "$work/stdout" "$work/stderr"
fi
# A part on which CGAL 5.5's boolean crashes (a constrained triangulation
# of a face whose cut points nearly coincide): exported, or one line that
# names the boolean, exit 1 and no file; never a crash.
cat > "$work/crash.lua" <<'LUA'
return union{
  cylinder{r=1, h=2}:translate(5,7,6), box(2):translate(2,2,6), box(2):translate(4,4,4),
  box{size={4,2,2}}:translate(4,2,0), box{size={4,2,2}}:translate(4,2,4),
  box{size={4,2,2}}:translate(6,2,6), box{size={4,2,2}}:translate(6,0,6),
  sphere(1):translate(5,5,5), sphere(1):translate(1,3,1), cylinder{r=1, h=2}:translate(5,5,2)
} - union{sphere(0.684):translate(7.359,1.794,0.803), sphere(1.035):translate(5.791,3.054,7.829)}
LUA
if "$csgray" export "$work/crash.lua" -o "$work/crash.stl" >/dev/null 2>&1 && [ -s "$work/crash.stl" ]; then
  pass
else
  expect_exit 1 "export CGAL crashes on" "$work/crash.stl" export "$work/crash.lua" -o "$work/crash.stl"
  expect_in_stderr "export CGAL crashes on" "crash.lua: "
fi
printf 'return torus{R=2, r=2}\n' > "$work/horn.lua"
expect_failure "export of a horn torus" "$work/horn.stl" export "$work/horn.lua" -o "$work/horn.stl"
expect_in_stderr "export of a horn torus" "horn torus"
# A sum that is not supported: one line naming the script's line, no file.
printf 'local ring = torus{R=3, r=1}\nreturn minkowski(ring, sphere(1))\n' > "$work/minkowski.lua"
expect_failure "export of an unsupported minkowski" "$work/minkowski.stl" export "$work/minkowski.lua" -o "$work/minkowski.stl"
expect_in_stderr "export of an unsupported minkowski" "minkowski.lua:2: minkowski: the torus is not convex; its sum is not supported"
expect_exit 2 "export with a zero tolerance" "$work/zero.stl" export "$work/part.lua" -o "$work/zero.stl" --tolerance 0
expect_exit 2 "export with a NaN tolerance" "$work/nan.stl" export "$work/part.lua" -o "$work/nan.stl" --tolerance nan
printf 'return sphere(1):translate(1e6, 0, 0)\n' > "$work/far.lua"
expect_failure "export far from the origin" "$work/far.stl" export "$work/far.lua" -o "$work/far.stl"
expect_in_stderr "export far from the origin" "32-bit floats are good to 0.06 only"
expect_failure "export over the script" "" export "$work/part.lua" -o "$work/part.lua"
expect_failure "export into a missing folder" "" export "$work/part.lua" -o "$work/nowhere/part.stl"
# A failed export leaves the old file as it was and no temporary behind.
printf 'old' > "$work/keep.stl"
expect_exit 1 "failed export keeps the old file" "" export "$work/horn.lua" -o "$work/keep.stl"
if [ "$(cat "$work/keep.stl")" = old ] && [ -z "$(ls -A "$work" | grep '^\.keep')" ]; then
  pass
else
  fail "a failed export changed keep.stl or left a temporary"
fi
# Open surfaces are left out, with a warning.
printf 'return scene{objects={box(1), plane{normal={0, 0, 1}, offset=0}}}\n' > "$work/floor.lua"
if "$csgray" export "$work/floor.lua" -o "$work/floor.stl" >/dev/null 2>"$work/stderr" && [ -s "$work/floor.stl" ]; then
  pass
else
  fail "export with a floor"; cat "$work/stderr"
fi
expect_in_stderr "export with a floor" "1 open surface is not exported"

# check: a sound part passes (exit 0), writes nothing, and says why.
before=$(ls -A "$work" | wc -l)
if "$csgray" check "$work/part.lua" --samples 2000 --grid 32 >"$work/stdout" 2>"$work/stderr" &&
   grep -q '^verdict: ok$' "$work/stdout" && grep -q 'classification  ok .* 0 disagree' "$work/stdout" &&
   [ "$(ls -A "$work" | wc -l)" -eq "$before" ]; then
  pass
else
  fail "good check"; cat "$work/stdout" "$work/stderr"
fi
if "$csgray" check "$work/part.lua" --samples 2000 --grid 32 --json >"$work/stdout" 2>"$work/stderr" &&
   grep -q '^  "ok": true,$' "$work/stdout" && grep -q '"disagree": 0' "$work/stdout" &&
   [ "$(head -c1 "$work/stdout")" = "{" ] && [ "$(tail -n1 "$work/stdout")" = "}" ]; then
  pass
else
  fail "check --json"; cat "$work/stdout" "$work/stderr"
fi
# A cutter flush with the top face: a warning, which --strict makes a failure.
printf 'local block = box(10)\nlocal slot = box{size={4, 12, 3}}:translate(3, -1, 7)\nreturn block - slot\n' > "$work/flush.lua"
if "$csgray" check "$work/flush.lua" --samples 2000 --grid 32 >"$work/stdout" 2>"$work/stderr" &&
   grep -qF 'warning: coincident faces: box (' "$work/stdout" &&
   grep -qF 'flush.lua:1) and box (' "$work/stdout" && grep -q '^verdict: ok$' "$work/stdout"; then
  pass
else
  fail "check warns of a shared face"; cat "$work/stdout" "$work/stderr"
fi
"$csgray" check "$work/flush.lua" --samples 2000 --grid 32 --strict >"$work/stdout" 2>"$work/stderr"
if [ $? -eq 1 ] && grep -q '^verdict: FAILED (strict: there are warnings)$' "$work/stdout"; then
  pass
else
  fail "check --strict fails on a warning"; cat "$work/stdout" "$work/stderr"
fi
# A part that cannot be exported fails the check, and says why.
"$csgray" check "$work/unbounded.lua" >"$work/stdout" 2>"$work/stderr"
if [ $? -eq 1 ] && grep -q 'the part is unbounded' "$work/stdout" && grep -q '^verdict: FAILED$' "$work/stdout"; then
  pass
else
  fail "check of an unbounded part"; cat "$work/stdout" "$work/stderr"
fi
expect_exit 1 "check of a bad script" "" check "$work/bad.lua"
expect_in_stderr "check of a bad script" "bad.lua:2: sphere: r must be > 0 (got -2)"
expect_exit 1 "check of a missing script" "" check "$work/nope.lua"
expect_exit 2 "check with negative samples" "" check "$work/part.lua" --samples -1
expect_exit 2 "check with a one-ray grid" "" check "$work/part.lua" --grid 1
expect_exit 2 "check with a zero tolerance" "" check "$work/part.lua" --tolerance 0
expect_exit 2 "check with a NaN wall" "" check "$work/part.lua" --min-wall nan

# ---- Files that are not regular files; long names; corrupt images ------------
# Each run here is under `timeout 10`, so that a FIFO that blocks fails the
# test (exit 124) instead of hanging the suite.
plain_csgray=$csgray
printf '#!/bin/sh\nexec timeout 10 "%s" "$@"\n' "$plain_csgray" > "$work/timed_csgray"
chmod +x "$work/timed_csgray"
csgray=$work/timed_csgray
mkdir "$work/special"
sp=$work/special
# Outputs that are not regular files are refused before the work, by name.
# As root, a rename over /dev/full would replace the device with the image:
# the same device is made in the work folder and tried first, and /dev/full
# itself only if that was refused.
if [ "$(id -u)" = 0 ] && mknod "$sp/full.png" c 1 7 2>/dev/null && mknod "$sp/full.stl" c 1 7 &&
   mknod "$sp/aov.depth.png" c 1 7; then
  :
else
  ln -sf /dev/full "$sp/full.png"; ln -sf /dev/full "$sp/full.stl"; ln -sf /dev/full "$sp/aov.depth.png"
fi
failed_before=$failed
expect_exit 1 "render to a full device" "" render "$work/part.lua" -o "$sp/full.png"
expect_in_stderr "render to a full device" "cannot write $sp/full.png: it is a character device, not a regular file"
expect_exit 1 "export to a full device" "" export "$work/part.lua" -o "$sp/full.stl"
expect_in_stderr "export to a full device" "cannot write $sp/full.stl: it is a character device, not a regular file"
expect_exit 1 "depth image to a full device" "$sp/aov.png" render "$work/part.lua" -o "$sp/aov.png" --aov depth
expect_in_stderr "depth image to a full device" "cannot write $sp/aov.depth.png: it is a character device"
if [ -c "$sp/full.png" ] && [ -c "$sp/full.stl" ] && [ -c "$sp/aov.depth.png" ]; then
  pass
else
  fail "a device output was replaced: $(ls -lA "$sp")"
fi
if [ "$failed" -eq "$failed_before" ]; then
  expect_exit 1 "render to /dev/full" "" render "$work/part.lua" -o /dev/full
  expect_in_stderr "render to /dev/full" "cannot write /dev/full: it is a character device, not a regular file"
  expect_exit 1 "export to /dev/full" "" export "$work/part.lua" -o /dev/full
  if [ -c /dev/full ] && [ ! -L /dev/full ]; then pass; else fail "/dev/full is no longer a device"; fi
fi
# A write that fails part way (a full disk; here the shell's file size
# limit of 8 KiB, with SIGXFSZ ignored so that write() fails with EFBIG):
# one line naming the file, the old file as it was, no temporary left.
# libjpeg ended the process on a failed write, leaving its temporary; the
# BMP and Targa writers reported a file with holes as written.
mkdir "$work/limited"
for format in png jpg exr bmp tga hdr tif stl obj off ply 3mf; do
  case $format in
    stl | obj | off | ply | 3mf) command=(export "$work/part.lua" --tolerance 0.01) ;;
    *) command=(render "$work/part.lua" --size 1024x768) ;;
  esac
  target=$work/limited/out.$format
  printf 'old\n' > "$target"
  (ulimit -f 8; trap '' XFSZ; "$csgray" "${command[@]}" -o "$target" >"$work/stdout" 2>"$work/stderr")
  code=$?
  if [ $code -ne 1 ] || [ "$(wc -l <"$work/stderr")" -ne 1 ] ||
     ! grep -qF "csgray: error: cannot write $target: " "$work/stderr"; then
    fail "$format past the file size limit: exit $code, stderr:"; cat "$work/stderr"
  elif [ "$(cat "$target")" != old ] || [ "$(ls -A "$work/limited" | wc -l)" -ne 1 ]; then
    fail "$format past the file size limit: $(ls -lA "$work/limited")"
  else
    pass
  fi
  rm -f "$target"
done
mkfifo "$sp/out.png" "$sp/out.stl" "$sp/out.obj" "$sp/aov2.normal.exr"
expect_exit 1 "render to a FIFO" "" render "$work/part.lua" -o "$sp/out.png"
expect_in_stderr "render to a FIFO" "cannot write $sp/out.png: it is a FIFO, not a regular file"
expect_exit 1 "export to a FIFO" "" export "$work/part.lua" -o "$sp/out.stl"
expect_in_stderr "export to a FIFO" "cannot write $sp/out.stl: it is a FIFO, not a regular file"
expect_exit 1 "export to a FIFO as text" "" export "$work/part.lua" -o "$sp/out.obj" --ascii
expect_exit 1 "normal image to a FIFO" "$sp/aov2.exr" render "$work/part.lua" -o "$sp/aov2.exr" --aov depth,normal
expect_in_stderr "normal image to a FIFO" "cannot write $sp/aov2.normal.exr: it is a FIFO"
if [ -p "$sp/out.png" ] && [ -p "$sp/out.stl" ] && [ -p "$sp/aov2.normal.exr" ] && [ ! -e "$sp/aov2.depth.exr" ]; then
  pass
else
  fail "a refused output changed the folder: $(ls -lA "$sp")"
fi
# Standard output that cannot be written is an error too (info's and
# check's reports would be lost).
"$csgray" info "$work/part.lua" >/dev/full 2>"$work/stderr"
if [ $? -eq 1 ] && [ "$(wc -l <"$work/stderr")" -eq 1 ] &&
   grep -q '^csgray: error: cannot write the standard output: ' "$work/stderr"; then
  pass
else
  fail "info > /dev/full"; cat "$work/stderr"
fi
"$csgray" check "$work/part.lua" --samples 200 --grid 8 >/dev/full 2>"$work/stderr"
if [ $? -eq 1 ] && [ "$(wc -l <"$work/stderr")" -eq 1 ] &&
   grep -q '^csgray: error: cannot write the standard output: ' "$work/stderr"; then
  pass
else
  fail "check > /dev/full"; cat "$work/stderr"
fi
# A FIFO as the script, as a mesh or as a texture fails at once, by name.
mkfifo "$sp/script.lua" "$sp/part.stl" "$sp/bricks.png"
expect_exit 1 "FIFO as the script" "$sp/s.png" render "$sp/script.lua" -o "$sp/s.png"
expect_in_stderr "FIFO as the script" "$sp/script.lua: cannot open script: it is a FIFO, not a regular file"
expect_exit 1 "FIFO as the script of info" "" info "$sp/script.lua"
printf 'return mesh{file="part.stl"}\n' > "$sp/mesh.lua"
expect_exit 1 "FIFO as a mesh" "$sp/m.png" render "$sp/mesh.lua" -o "$sp/m.png"
expect_in_stderr "FIFO as a mesh" "mesh.lua:1: mesh: part.stl: it is a FIFO, not a regular file"
printf 'return box(1):material{color=image_texture{file="bricks.png"}}\n' > "$sp/texture.lua"
expect_exit 1 "FIFO as a texture" "$sp/t.png" render "$sp/texture.lua" -o "$sp/t.png"
expect_in_stderr "FIFO as a texture" "bricks.png: it is a FIFO, not a regular file"
# A texture that is a device is refused too; a script may be one (see
# /dev/zero above).
printf 'return box(1):material{color=image_texture{file="/dev/zero"}}\n' > "$sp/zero.lua"
expect_exit 1 "device as a texture" "$sp/z.png" render "$sp/zero.lua" -o "$sp/z.png" --allow-path /dev
expect_in_stderr "device as a texture" "/dev/zero: it is a character device, not a regular file"
# An output name of 250 bytes is written (its temporary's name is cut to
# fit the 255-byte limit); one over the limit is refused before the work.
long=$(printf 'n%.0s' $(seq 246))
mkdir "$work/long"
if "$csgray" render "$work/part.lua" -o "$work/long/$long.png" --size 16x12 >/dev/null 2>"$work/stderr" &&
   is_png "$work/long/$long.png" &&
   "$csgray" export "$work/part.lua" -o "$work/long/$long.stl" >/dev/null 2>>"$work/stderr" &&
   [ -s "$work/long/$long.stl" ] && [ "$(ls -A "$work/long" | wc -l)" -eq 2 ]; then
  pass
else
  fail "a 250-byte output name"; cat "$work/stderr"; ls -A "$work/long"
fi
rm -rf "$work/long"
mkdir "$work/long"
expect_exit 1 "a 256-byte output name" "" render "$work/part.lua" -o "$work/long/${long}nnnnnn.png"
expect_in_stderr "a 256-byte output name" "the file name is longer than 255 bytes"
# Its depth image's name would be longer than the limit: refused before the
# colour image is written.
expect_exit 1 "a depth image name over the limit" "" render "$work/part.lua" -o "$work/long/$long.png" --aov depth
expect_in_stderr "a depth image name over the limit" "cannot write $work/long/$long.depth.png: the file name is longer"
if [ -z "$(ls -A "$work/long")" ]; then pass; else fail "long names left: $(ls -A "$work/long")"; fi
# Corrupt texture images: one line that names the file, and nothing that
# libpng or OpenImageIO print themselves.
mkdir "$work/corrupt"
cr=$work/corrupt
"$csgray" render "$work/part.lua" -o "$cr/good.png" --size 64x48 >/dev/null 2>&1
"$csgray" render "$work/part.lua" -o "$cr/good.jpg" --size 64x48 >/dev/null 2>&1
for ext in png jpg; do
  size=$(wc -c <"$cr/good.$ext")
  head -c $((size / 2)) "$cr/good.$ext" >"$cr/half.$ext"
  head -c 40 "$cr/good.$ext" >"$cr/head.$ext"
  cp "$cr/good.$ext" "$cr/junk.$ext"
  printf '\245\245\245\245\245\245\245\245\245\245\245\245' |
    dd of="$cr/junk.$ext" bs=1 seek=$((size / 2)) conv=notrunc 2>/dev/null
done
for image in half.png head.png junk.png half.jpg head.jpg; do
  printf 'return box(1):material{color=image_texture{file="%s"}}\n' "$image" > "$cr/tex.lua"
  expect_exit 1 "corrupt texture $image" "$cr/out.png" render "$cr/tex.lua" -o "$cr/out.png"
  expect_in_stderr "corrupt texture $image" "tex.lua:1: image_texture: $image: "
done
csgray=$plain_csgray
# ---- options refused, and the limits of a run (docs/cli.md, "What is refused
# on the command line" and "Limits of a run")
# Each: the exit code (2 for the command line, 1 for the run) and one line.
short_stderr() {  # NAME: the line is short, whatever the command line held
  if [ "$(wc -c <"$work/stderr")" -le 300 ]; then pass; else fail "$1: $(wc -c <"$work/stderr") bytes on stderr"; fi
}
expect_exit 2 "seed past 64 bits" "" check "$work/part.lua" --seed 18446744073709551616
expect_in_stderr "seed past 64 bits" "--seed: must be a whole number below 2^64"
expect_exit 2 "seed written with an exponent" "" check "$work/part.lua" --seed 1e30
expect_exit 2 "threads in hexadecimal" "$work/out.png" render "$work/part.lua" -o "$work/out.png" --threads 0x10
# -D: a denormal is a finite number and is taken; what is refused is a
# command-line error that says why.
if "$csgray" info "$work/param.lua" -D radius=4.9e-324 >"$work/stdout" 2>"$work/stderr" &&
   grep -q '4.94066e-324' "$work/stdout"; then pass; else fail "-D radius=4.9e-324"; cat "$work/stderr"; fi
# -D takes vectors, and is checked against a parameter's annotation
# (docs/view.md) on every command.
printf 'return box{size=size}\n' > "$work/vector.lua"
if "$csgray" info "$work/vector.lua" -D 'size={90,60,30}' >"$work/stdout" 2>"$work/stderr" &&
   grep -q 'bounds: *\[0, 0, 0\] \.\. \[90, 60, 30\]' "$work/stdout"; then pass; else
  fail "-D size={90,60,30}"; cat "$work/stderr"; fi
printf 'width = 40 -- [10:100] the width\nreturn box{size={width, 1, 1}}\n' > "$work/annotated.lua"
if "$csgray" info "$work/annotated.lua" -D width=25 >"$work/stdout" 2>"$work/stderr" &&
   grep -q '\[25, 1, 1\]' "$work/stdout"; then pass; else fail "-D replaces an annotated default"; cat "$work/stderr"; fi
for command in render export check info; do
  output=()
  [ $command = render ] && output=(-o "$work/out.png")
  [ $command = export ] && output=(-o "$work/out.stl")
  expect_exit 2 "annotated define ($command)" "" $command "$work/annotated.lua" "${output[@]}" -D width=500
  expect_in_stderr "annotated define ($command)" "-D width=500: width must be from 10 to 100 ($work/annotated.lua:1)"
done
# render --watch renders again when the script is saved (by a rename, as
# editors do), says why a broken save fails, and renders the fixed one.
printf 'return box(1)\n' > "$work/watched.lua"
"$csgray" render "$work/watched.lua" -o "$work/watched.png" --size 16x16 --watch >"$work/watch.out" 2>"$work/watch.err" &
watcher=$!
wait_for() {  # wait_for FILE PATTERN COUNT: up to 20 s for COUNT lines matching
  for _ in $(seq 200); do
    [ "$(grep -c -- "$2" "$1")" -ge "$3" ] && return 0
    sleep 0.1
  done
  return 1
}
if wait_for "$work/watch.out" "watching" 1; then
  printf 'return box(\n' > "$work/watched.tmp" && mv "$work/watched.tmp" "$work/watched.lua"
  wait_for "$work/watch.err" "watched.lua:2:" 1 && pass || fail "render --watch: no error for a broken save"
  printf 'return sphere(1)\n' > "$work/watched.tmp" && mv "$work/watched.tmp" "$work/watched.lua"
  wait_for "$work/watch.out" "wrote $work/watched.png" 2 && pass || fail "render --watch: no second render"
else
  fail "render --watch did not start"; cat "$work/watch.err"
fi
kill "$watcher"; wait "$watcher" 2>/dev/null
expect_exit 2 "view with --timeout" "" view "$work/annotated.lua" --timeout 5
# ... and its help does not offer it.
if "$csgray" view --help 2>&1 | grep -q -- " --timeout"; then fail "view --help lists --timeout"; else pass; fi
# A string pattern that backtracks for hours, inside one library call that
# no instruction budget sees: view ends at --script-timeout, rather than
# hold the script's thread (and every reload) for ever.
timeout 60 "$csgray" view "$work/pattern.lua" --port 0 --script-timeout 0.5 \
  >"$work/stdout" 2>"$work/stderr"
code=$?
if [ $code -eq 1 ] &&
   grep -q "pattern.lua: the script did not finish within 0.5 s (--script-timeout); csgray view ends here" \
     "$work/stderr"; then pass; else fail "view of a backtracking pattern: exit $code"; cat "$work/stderr"; fi
expect_exit 2 "render --watch with --timeout" "" render "$work/annotated.lua" -o "$work/out.png" --watch --timeout 5
# A second view on the port the first listens on is refused, as a port
# held by any other program is (they shared it, and the kernel sent the
# page's requests to either part).
timeout 30 "$csgray" view "$work/annotated.lua" --port 0 >"$work/first.out" 2>&1 &
first_view=$!
if wait_for "$work/first.out" "viewing" 1; then
  port=$(grep -o '127.0.0.1:[0-9]*' "$work/first.out" | head -1 | cut -d: -f2)
  expect_exit 1 "view on a port in use" "" view "$work/annotated.lua" --port "$port"
  expect_in_stderr "view on a port in use" "cannot listen on 127.0.0.1:$port (is the port in use?)"
else
  fail "the first view did not start"; cat "$work/first.out"
fi
kill "$first_view"; wait "$first_view" 2>/dev/null
# A -D refused by an annotation of thousands of choices, or a vector of
# thousands of numbers, says so on one short line.
{ printf 's = "a" -- ['; for i in $(seq 1 3000); do printf '"c%d", ' "$i"; done; printf '"a"] kind\n'
  printf 'v = {'; for i in $(seq 1 3000); do printf '1, '; done; printf '1} -- []\n'
  printf 'return box(1)\n'; } > "$work/many_choices.lua"
expect_exit 2 "a refused choice of thousands" "" info "$work/many_choices.lua" -D s=zz
expect_in_stderr "a refused choice of thousands" 's must be one of "c1", "c2"'
expect_in_stderr "a refused choice of thousands" "and 2989 more"
short_stderr "a refused choice of thousands"
expect_exit 2 "a refused vector of thousands" "" info "$work/many_choices.lua" -D 'v={1}'
short_stderr "a refused vector of thousands"
expect_exit 2 "define past the range of a double" "$work/out.png" render "$work/param.lua" -o "$work/out.png" -D radius=1e999
expect_in_stderr "define past the range of a double" "-D radius=1e999: out of range"
expect_exit 2 "define that underflows to 0" "" info "$work/param.lua" -D radius=1e-400
expect_in_stderr "define that underflows to 0" "-D radius=1e-400: too close to 0"
expect_exit 2 "define of NaN" "" info "$work/param.lua" -D radius=nan
expect_in_stderr "define of NaN" "-D radius=nan: not a finite number"
expect_exit 2 "define without a value" "" info "$work/param.lua" -D radius
expect_exit 2 "define of a built-in" "" info "$work/param.lua" -D sphere=3
expect_exit 2 "define of a keyword" "" info "$work/param.lua" -D end=3
# Values of 100 000 characters are cut in the message.
huge=$(head -c 100000 /dev/zero | tr '\0' 9)
expect_exit 2 "huge define" "" info "$work/param.lua" -D "radius=${huge}"
# The first 40 characters, "...", the last 17.
expect_in_stderr "huge define" "-D radius=$(head -c 40 <<<"$huge")...$(head -c 17 <<<"$huge"): out of range"
short_stderr "huge define"
expect_exit 2 "huge define without a value" "" info "$work/param.lua" -D "$huge"
short_stderr "huge define without a value"
expect_exit 2 "huge size" "$work/out.png" render "$work/part.lua" -o "$work/out.png" --size "$huge"
short_stderr "huge size"
expect_exit 2 "huge unknown option" "" info "$work/param.lua" "--$huge"
short_stderr "huge unknown option"
# An unknown command is named.
expect_exit 2 "unknown command" "" rendr "$work/part.lua" -o "$work/out.png"
expect_in_stderr "unknown command" "csgray: error: unknown command 'rendr'; the commands are render, export, check, info and view"
expect_exit 2 "huge unknown command" "" "$huge"
short_stderr "huge unknown command"

# The work of a render is bounded before it starts: 2000 area lights of
# 1024 samples at the default size is refused with its figure, exit 1.
printf 'local lights = {}\nfor i = 1, 2000 do lights[i] = sphere_light{pos={i, 0, 5}, samples=1024} end\nreturn scene{objects={sphere(1)}, lights=lights}\n' > "$work/lights.lua"
expect_exit 1 "render of 2000 area lights" "$work/lights.png" render "$work/lights.lua" -o "$work/lights.png"
expect_in_stderr "render of 2000 area lights" "lights.lua: the render would trace up to 9.8e+11 rays (480000 camera rays × up to 1 ray each × (1 + 2048000 shadow rays from 2000 lights)); at most 1e+11 are allowed (--max-rays)"
expect_exit 2 "negative --max-rays" "$work/out.png" render "$work/part.lua" -o "$work/out.png" --max-rays -1
expect_exit 2 "NaN --max-rays" "$work/out.png" render "$work/part.lua" -o "$work/out.png" --max-rays nan

# --timeout ends a whole run that would take minutes: one line, exit 1, no
# output file and an old one as it was. Under timeout(1), so that a limit
# that fails cannot hang the tests; nothing is asserted about the time.
printf '#!/bin/sh\nexec timeout 30 "%s" "$@"\n' "$csgray" > "$work/csgray30" && chmod +x "$work/csgray30"
csgray_itself=$csgray
csgray=$work/csgray30
printf 'local lights = {}\nfor i = 1, 40 do lights[i] = sphere_light{pos={2, -2, 5 + i}, samples=1024} end\nreturn scene{objects={sphere(1)}, lights=lights}\n' > "$work/slow_lights.lua"
expect_exit 1 "render past --timeout" "$work/slow_lights.png" render "$work/slow_lights.lua" -o "$work/slow_lights.png" --timeout 1
expect_in_stderr "render past --timeout" "slow_lights.lua: the render took longer than --timeout 1 s"
# The refused render of 2000 lights, let through: the limit ends it too.
printf 'old' > "$work/lights.png"
expect_exit 1 "render let past --max-rays" "" render "$work/lights.lua" -o "$work/lights.png" --max-rays 0 --timeout 1
expect_in_stderr "render let past --max-rays" "lights.lua: the render took longer than --timeout 1 s"
if [ "$(cat "$work/lights.png")" = old ]; then pass; else fail "a render past --timeout changed the old image"; fi
cat > "$work/holes.lua" <<'LUA'
local part = box(20)
for i = 1, 400 do
  part = part - sphere(0.7):translate(1 + (i * 7.3) % 18, 1 + (i * 3.1) % 18, 1 + (i * 5.7) % 18)
end
return part
LUA
printf 'old' > "$work/holes.stl"
expect_exit 1 "export past --timeout" "" export "$work/holes.lua" -o "$work/holes.stl" --tolerance 0.001 --timeout 1
expect_in_stderr "export past --timeout" "holes.lua: the export took longer than --timeout 1 s"
if [ "$(cat "$work/holes.stl")" = old ] && [ -z "$(ls -A "$work" | grep '^\.holes')" ]; then
  pass
else
  fail "an export past --timeout changed the old file or left a temporary"
fi
expect_exit 1 "check past --timeout" "" check "$work/holes.lua" --tolerance 0.001 --timeout 1
expect_in_stderr "check past --timeout" "holes.lua: the check took longer than --timeout 1 s"
if [ ! -s "$work/stdout" ]; then pass; else fail "a check past --timeout printed a report"; fi
# A part past where 32-bit floats hold the tolerance: export and check
# refuse it alike, before any mesh (the check made one of 1.3 GB first).
printf 'return sphere(1e18)\n' > "$work/far.lua"
expect_exit 1 "export of a far part" "" export "$work/far.lua" -o "$work/far.stl" --timeout 10
expect_in_stderr "export of a far part" "far.lua: the part reaches 1e+18 from the origin"
expect_exit 1 "check of a far part" "" check "$work/far.lua" --timeout 10
expect_in_stderr "check of a far part" "far.lua: the part reaches 1e+18 from the origin"
# info's bounds by rays of a part of 400 letters take about 20 s; --timeout
# ends them too.
printf 'return linear_extrude{text{string.rep("W", 400)}, height=1}\n' > "$work/letters.lua"
expect_exit 1 "info past --timeout" "" info "$work/letters.lua" --timeout 1
expect_in_stderr "info past --timeout" "letters.lua: the info command took longer than --timeout 1 s"
# The script's time counts: --timeout ends it even below --script-timeout.
expect_exit 1 "script past --timeout" "" info "$work/pattern.lua" --timeout 0.5
expect_in_stderr "script past --timeout" "pattern.lua: the info command took longer than --timeout 0.5 s"
csgray=$csgray_itself
expect_exit 2 "negative --timeout" "" info "$work/part.lua" --timeout -1
# A run within its limit is not touched.
if "$csgray" render "$work/part.lua" -o "$work/timed.png" --size 32x24 --timeout 60 >/dev/null 2>&1 &&
   [ -s "$work/timed.png" ]; then pass; else fail "a render within --timeout"; fi

# A mesh file with a vertex of two coordinates, through a script: the file
# and line, exit 1.
printf 'ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n' > "$work/short_row.ply"
printf 'return mesh{file="short_row.ply"}\n' > "$work/short_row.lua"
expect_exit 1 "mesh with a short vertex row" "$work/out.png" render "$work/short_row.lua" -o "$work/out.png"
expect_in_stderr "mesh with a short vertex row" "short_row.ply:11: vertex 1: the line ends before the values the header declares"

# ---- bad scripts: the sandbox's limits and the API's arguments --------------
# Each ends with exit 1, one line naming the script's line, and no image.
printf 'local ok = pcall(string.rep, "x", 1 << 30)\nreturn sphere(1)\n' > "$work/caught_memory.lua"
printf 'local function f() pcall(f) pcall(f) end\nf()\nreturn sphere(1)\n' > "$work/doubling.lua"
printf 'local s = sphere(1)\nfor i = 1, 25 do s = s + s:translate(1, 0, 0) end\nreturn s\n' \
  > "$work/uses.lua"
printf 'return sphere(1, 2)\n' > "$work/extra_argument.lua"
printf 'local s = sphere(1)\nsetmetatable(s, {})\nreturn s\n' > "$work/solid_metatable.lua"
expect_exit 1 "memory error under pcall" "$work/out.png" render "$work/caught_memory.lua" -o "$work/out.png"
expect_in_stderr "memory error under pcall" "caught_memory.lua:1: script exceeded the memory limit of 1024 MiB"
# Before the time limit: the errors caught count against the budget.
expect_exit 1 "doubling recursion" "$work/out.png" render "$work/doubling.lua" -o "$work/out.png" \
  --script-timeout 30
expect_in_stderr "doubling recursion" "doubling.lua:1: script exceeded the instruction budget"
# (Moved uses of a part share it: the limit on primitives, which counts
# uses, stops the doubling.)
expect_exit 1 "uses in a union" "$work/out.png" render "$work/uses.lua" -o "$work/out.png"
expect_in_stderr "uses in a union" "uses.lua:2: union: the part would have more than 2000000 primitives"
expect_exit 1 "extra argument" "$work/out.png" render "$work/extra_argument.lua" -o "$work/out.png"
expect_in_stderr "extra argument" "extra_argument.lua:1: sphere: takes 1 argument (got 2)"
expect_exit 1 "metatable of a solid" "$work/out.png" render "$work/solid_metatable.lua" -o "$work/out.png"
expect_in_stderr "metatable of a solid" \
  "solid_metatable.lua:2: setmetatable: a solid cannot take a metatable; only a table can"

# ---- 2D regions: outlines as SVG and DXF, refused as meshes -----------------
printf 'local plate = square{size=40, center=true}\nreturn plate - circle{r=8} - circle(3):translate(14, 14)\n' \
  > "$work/plate2d.lua"
printf 'return scene{objects={box(1), circle(1)}}\n' > "$work/mixed2d.lua"
printf 'return square(10):rotate(90, 0, 0)\n' > "$work/wall2d.lua"
printf 'local r = circle(1)\nreturn polygon{{0, 0}, {1, 1}, {2, 2}}\n' > "$work/collinear2d.lua"
for ext in svg dxf SVG; do
  if "$csgray" export "$work/plate2d.lua" -o "$work/plate.$ext" >"$work/stdout" 2>"$work/stderr" &&
    [ -s "$work/plate.$ext" ] && grep -q "wrote $work/plate.$ext (3 loops, area 1370.66)" "$work/stdout"; then
    pass
  else
    fail "outline .$ext"; cat "$work/stdout" "$work/stderr"
  fi
done
grep -q '<path fill="none" fill-rule="evenodd"' "$work/plate.svg" && grep -q ' A 8 8 0 ' "$work/plate.svg" &&
  pass || fail "the SVG outline has no arc of the hole"
grep -q '^CIRCLE$\|^ARC$' "$work/plate.dxf" && tail -1 "$work/plate.dxf" | grep -q '^EOF$' &&
  pass || fail "the DXF outline has no arc or no EOF"
# Solids beside regions are left out with a warning.
if "$csgray" export "$work/mixed2d.lua" -o "$work/mixed.svg" >"$work/stdout" 2>"$work/stderr" &&
  grep -q "1 solid or surface is not outlined" "$work/stderr"; then pass; else fail "mixed outline"; cat "$work/stderr"; fi
expect_exit 1 "a region exported as a mesh" "$work/plate.stl" export "$work/plate2d.lua" -o "$work/plate.stl"
expect_in_stderr "a region exported as a mesh" \
  "plate2d.lua: the 2D region is not a solid, so it has no mesh: extrude it (linear_extrude, rotate_extrude) or export its outline to .svg or .dxf"
# So is it in a check (and in csgray view's export and check).
expect_exit 1 "a region checked" "" check "$work/plate2d.lua"
expect_in_stderr "a region checked" \
  "plate2d.lua: the 2D region is not a solid, so it has no mesh: extrude it (linear_extrude, rotate_extrude) or export its outline to .svg or .dxf"
expect_exit 1 "a solid outlined" "$work/part.svg" export "$work/part.lua" -o "$work/part.svg"
expect_in_stderr "a solid outlined" "part.lua: there is no 2D region to outline"
expect_exit 1 "a region stood up" "$work/wall.svg" export "$work/wall2d.lua" -o "$work/wall.svg"
expect_in_stderr "a region stood up" \
  "wall2d.lua: a square placed in space by a 3D transform has no outline in the plane z = 0"
expect_exit 1 "an unknown outline format" "" export "$work/plate2d.lua" -o "$work/plate.eps"
expect_exit 1 "a collinear polygon" "$work/bad.svg" export "$work/collinear2d.lua" -o "$work/bad.svg"
expect_in_stderr "a collinear polygon" \
  "collinear2d.lua:2: polygon: the points are collinear, so they enclose no area"
# A region renders, flat in the plane z = 0.
if "$csgray" render "$work/plate2d.lua" -o "$work/plate.png" --size 64x48 >/dev/null 2>"$work/stderr" &&
  [ -s "$work/plate.png" ]; then pass; else fail "render a region"; cat "$work/stderr"; fi


# OpenSCAD's .csg files open as parts, exact or with OpenSCAD's facets;
# a bad one is one line naming the file and line, and writes nothing.
printf 'difference() {\n  cube(size = [10, 10, 10]);\n  cylinder($fn = 6, h = 30, r1 = 2, r2 = 2, center = true);\n}\n' > "$work/part.csg"
printf 'group() {\n  cube(size = [1, 1, 1]);\n  frobnicate(r = 2);\n}\n' > "$work/unknown.csg"
printf 'group() {\n  cube(size = [1, 1, 1]\n' > "$work/broken.csg"
if "$csgray" render "$work/part.csg" -o "$work/csg.png" --size 64x48 >/dev/null 2>"$work/stderr" &&
  [ -s "$work/csg.png" ]; then pass; else fail "render a .csg file"; cat "$work/stderr"; fi
if "$csgray" export "$work/part.csg" -o "$work/csg.stl" --facets openscad >"$work/stdout" 2>"$work/stderr" &&
  grep -q "volume 974.019" "$work/stdout"; then pass; else fail "export a .csg file"; cat "$work/stderr"; fi
if "$csgray" check "$work/part.csg" >/dev/null 2>"$work/stderr"; then pass; else fail "check a .csg file"; cat "$work/stderr"; fi
expect_exit 1 "an unknown .csg node" "$work/unknown.png" render "$work/unknown.csg" -o "$work/unknown.png"
expect_in_stderr "an unknown .csg node" "unknown.csg:3: frobnicate: unknown node"
expect_exit 1 "a broken .csg file" "$work/broken.stl" export "$work/broken.csg" -o "$work/broken.stl"
expect_in_stderr "a broken .csg file" "broken.csg:3: expected ',' or ')' between the arguments of cube, found the end of the file"
expect_failure "a bad --facets" "" export "$work/part.csg" -o "$work/facets.stl" --facets round
# Files a .csg node reads: a DXF drawing cut short, a height map with a
# word among its numbers; the error names the .csg line and the file's.
printf 'linear_extrude(height = 2) {\n  import(file = "cut.dxf", layer = "");\n}\n' > "$work/dxf.csg"
printf '0\nSECTION\n2\nENTITIES\n0\nCIRCLE\n40\n5\n' > "$work/cut.dxf"
expect_exit 1 "a DXF file cut short" "$work/dxf.stl" export "$work/dxf.csg" -o "$work/dxf.stl"
expect_in_stderr "a DXF file cut short" "dxf.csg:2: import: cut.dxf:8: the file ends inside the ENTITIES section"
printf 'surface(file = "words.dat", center = true);\n' > "$work/surface.csg"
printf '1 2\n3 four\n' > "$work/words.dat"
expect_exit 1 "a height map with a word" "$work/surface.stl" export "$work/surface.csg" -o "$work/surface.stl"
expect_in_stderr "a height map with a word" "surface.csg:1: surface: words.dat:2: 'four' is not a number"
# The whole file: a circle of r = 5 as OpenSCAD's 16-gon (2π·5/$fs = 15.7
# sides, rounded up), 2 high: 2 · 8 · 25 · sin(22.5°).
printf '0\nSECTION\n2\nENTITIES\n0\nCIRCLE\n40\n5\n0\nENDSEC\n0\nEOF\n' > "$work/cut.dxf"
if "$csgray" export "$work/dxf.csg" -o "$work/dxf.stl" --facets openscad >"$work/stdout" 2>"$work/stderr" &&
  grep -q "volume 153.073" "$work/stdout"; then pass; else fail "export a .csg file's DXF"; cat "$work/stdout" "$work/stderr"; fi

# An SVG drawing, from a .csg file and from a script: one cut short is a
# one-line error naming both lines; a whole one, a 20 × 10 mm rectangle
# (a viewBox of 40 × 20 on a 20 × 10 mm page) 2 high, has volume 400.
printf 'linear_extrude(height = 2) {\n  import(file = "cut.svg", center = false, dpi = 72);\n}\n' > "$work/svg.csg"
printf '<svg width="20mm" height="10mm" viewBox="0 0 40 20">\n<rect width="40" height="20"/>\n<g>\n' > "$work/cut.svg"
expect_exit 1 "an SVG file cut short" "$work/svg.stl" export "$work/svg.csg" -o "$work/svg.stl"
expect_in_stderr "an SVG file cut short" "svg.csg:2: import: cut.svg:3: <g> is not closed: the file ends first (is it cut short?)"
printf 'return linear_extrude{import_svg{file="cut.svg"}, height=2}\n' > "$work/svg.lua"
expect_exit 1 "a script's SVG file cut short" "$work/svg.stl" export "$work/svg.lua" -o "$work/svg.stl"
expect_in_stderr "a script's SVG file cut short" "svg.lua:1: import_svg: cut.svg:3: <g> is not closed"
printf '</g>\n</svg>\n' >> "$work/cut.svg"
for part in svg.csg svg.lua; do
  if "$csgray" export "$work/$part" -o "$work/svg.stl" >"$work/stdout" 2>"$work/stderr" &&
    grep -q "volume 400)" "$work/stdout"; then pass; else fail "export $part's SVG"; cat "$work/stdout" "$work/stderr"; fi
done

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
