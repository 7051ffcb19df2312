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

# info prints the bounds and the tree.
if "$csgray" info "$work/part.lua" >"$work/stdout" 2>&1 &&
   grep -q 'bounds: *\[0, 0, 0\] \.\. \[10, 20, 5\]' "$work/stdout" &&
   grep -q 'primitives: *2' "$work/stdout" && grep -q 'boolean nodes: *1' "$work/stdout"; then
  pass
else
  fail "info"; cat "$work/stdout"
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
expect_in_stderr "table error" "table_error.lua: error(table) without a message"
expect_failure "multi-line error" "$work/out.png" render "$work/multiline.lua" -o "$work/out.png"
expect_in_stderr "multi-line error" "multiline.lua:1: first second"
expect_failure "unbounded without camera" "$work/out.png" render "$work/unbounded.lua" -o "$work/out.png"
expect_in_stderr "unbounded without camera" "unbounded.lua: cannot frame an unbounded solid"
expect_failure "NaN timeout" "$work/out.png" render "$work/part.lua" -o "$work/out.png" --script-timeout nan
expect_failure "huge timeout" "$work/out.png" render "$work/part.lua" -o "$work/out.png" --script-timeout 1e10
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
expect_failure "negative threads" "$work/out.png" render "$work/part.lua" -o "$work/out.png" --threads -1
expect_failure "unknown format" "$work/out.xyz" render "$work/part.lua" -o "$work/out.xyz"
expect_in_stderr "unknown format" "unknown image format '.xyz'"
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
expect_exit 2 "adaptive without samples" "$work/out.png" render "$work/part.lua" -o "$work/out.png" --adaptive
expect_in_stderr "adaptive without samples" "--samples"
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
if "$csgray" render "$work/slow.lua" -o "$work/slow.png" --size 64x48 --threads 1 --samples 4 \
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
  script -qec "'$csgray' render '$work/slow.lua' -o '$work/slow.png' --size 64x48 --threads 1 --samples 4" \
    /dev/null >"$work/tty" 2>&1
  case "$seconds" in
    0.*) echo "note: the render took $seconds s, under the bar's 1 s: the terminal check is skipped";;
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
# Bad exports: one line, exit 1 (2 for the command line), no file.
expect_failure "export of an unknown format" "$work/part.xyz" export "$work/part.lua" -o "$work/part.xyz"
expect_in_stderr "export of an unknown format" "unknown mesh format '.xyz'"
expect_failure "export of an unbounded part" "$work/unbounded.stl" export "$work/unbounded.lua" -o "$work/unbounded.stl"
expect_in_stderr "export of an unbounded part" "unbounded.lua: the part is unbounded"
# Boxes that share only an edge are joined (docs/cli.md, "Contacts").
printf 'return box(1) + box(1):translate(1, 1, 0)\n' > "$work/edge.lua"
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

# ---- bad scripts: the sandbox's limits and the API's arguments --------------
# Each ends with exit 1, one line naming the script's line, and no image.
printf 'local ok = pcall(string.rep, "x", 1 << 30)\nreturn sphere(1)\n' > "$work/caught_memory.lua"
printf 'local function f() pcall(f) pcall(f) end\nf()\nreturn sphere(1)\n' > "$work/doubling.lua"
printf 'local s = sphere(1)\nfor i = 1, 25 do s = s + s:translate(1, 0, 0) end\nreturn s\n' \
  > "$work/copies.lua"
printf 'return sphere(1, 2)\n' > "$work/extra_argument.lua"
printf 'local s = sphere(1)\nsetmetatable(s, {})\nreturn s\n' > "$work/solid_metatable.lua"
expect_exit 1 "memory error under pcall" "$work/out.png" render "$work/caught_memory.lua" -o "$work/out.png"
expect_in_stderr "memory error under pcall" "caught_memory.lua:1: script exceeded the memory limit of 1024 MiB"
# Before the time limit: the errors caught count against the budget.
expect_exit 1 "doubling recursion" "$work/out.png" render "$work/doubling.lua" -o "$work/out.png" \
  --script-timeout 30
expect_in_stderr "doubling recursion" "doubling.lua:1: script exceeded the instruction budget"
expect_exit 1 "copies in a union" "$work/out.png" render "$work/copies.lua" -o "$work/out.png"
expect_in_stderr "copies in a union" "copies.lua:2: script exceeded the memory limit of 1024 MiB"
expect_exit 1 "extra argument" "$work/out.png" render "$work/extra_argument.lua" -o "$work/out.png"
expect_in_stderr "extra argument" "extra_argument.lua:1: sphere: takes 1 argument (got 2)"
expect_exit 1 "metatable of a solid" "$work/out.png" render "$work/solid_metatable.lua" -o "$work/out.png"
expect_in_stderr "metatable of a solid" \
  "solid_metatable.lua:2: setmetatable: a solid cannot take a metatable; only a table can"

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
