#!/usr/bin/env bash
# The csgray command line: good input works; bad input gets one line on
# stderr, a non-zero exit, and leaves no output file (and an old one as it was).
set -u
csgray=$1
source_dir=$2
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

# expect_failure NAME OUTPUT-FILE-OR-"" ARGS...: non-zero exit, exactly one
# line on stderr that starts with "csgray: error:", and no output file.
expect_failure() {
  local name=$1 output=$2
  shift 2
  "$csgray" "$@" >"$work/stdout" 2>"$work/stderr"
  local code=$?
  local lines
  lines=$(wc -l <"$work/stderr")
  if [ $code -eq 0 ]; then
    fail "$name: exit code 0"
  elif [ $code -ge 128 ]; then
    fail "$name: crashed with exit code $code"
  elif [ "$lines" -ne 1 ] || ! grep -q '^csgray: error: ' "$work/stderr"; then
    fail "$name: stderr is not one 'csgray: error:' line:"; cat "$work/stderr"
  elif [ -n "$output" ] && [ -e "$output" ]; then
    fail "$name: left $output behind"
  else
    pass
  fi
}

expect_in_stderr() {
  if grep -qF -- "$2" "$work/stderr"; then pass; else fail "$1: stderr lacks '$2':"; cat "$work/stderr"; fi
}

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
if [ "$(id -u)" != 0 ]; then
  mkdir "$work/readonly" && chmod 555 "$work/readonly"
  expect_failure "read-only folder" "$work/readonly/out.png" render "$work/part.lua" -o "$work/readonly/out.png"
fi

# No temporary files are left anywhere in the work folder.
if ls -A "$work" | grep -q '\.tmp'; then fail "temporary files left: $(ls -A "$work")"; else pass; fi

# The showcase renders from the command line.
if "$csgray" render "$source_dir/examples/showcase.lua" -o "$work/showcase.png" --size 80x60 >/dev/null 2>&1 &&
   [ -s "$work/showcase.png" ]; then pass; else fail "showcase"; fi

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
