#!/bin/sh
# The library as a user gets it: `cmake --install` into a temporary prefix,
# its headers compiled on their own, the csgray command run from there, and examples/cpp configured with
# find_package(csgray) against it, built and run. Its image must be a PNG of the size it asked for; its STL must hold
# triangles whose volume is the part's analytic volume, read back by a
# program built against the same install with pkg-config (csgray.pc).
#
# install_test.sh CMAKE BUILD_DIR SOURCE_DIR CXX
set -eu
cmake=$1 build=$2 source=$3 cxx=$4

tmp=$(mktemp -d "${TMPDIR:-/tmp}/csgray_install_test.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
trap 'exit 1' INT TERM
fail() {
  echo "install_test: $*" >&2
  exit 1
}

"$cmake" --install "$build" --prefix "$tmp/prefix" >"$tmp/install.log" 2>&1 ||
  { cat "$tmp/install.log" >&2; fail "cmake --install failed"; }
for f in include/csgray/csgray.h include/csgray/solid.h; do
  [ -f "$tmp/prefix/$f" ] || fail "$f was not installed"
done
# No internal header is reachable from the public ones.
if grep -rhE '#include *"' "$tmp/prefix/include/csgray" | grep -vE '"csgray/[a-z_]+\.h"'; then
  fail "a public header includes a header outside include/csgray/"
fi
if grep -rhE '#include *<(glm|CGAL|OpenMesh|OpenImageIO|lua)' "$tmp/prefix/include/csgray"; then
  fail "a public header includes a dependency's header"
fi

# Each public header compiles on its own under the strictest warnings a
# user may build with.
for header in "$tmp"/prefix/include/csgray/*.h; do
  printf '#include "csgray/%s"\n' "$(basename "$header")" >"$tmp/header.cpp"
  "$cxx" -std=c++17 -I"$tmp/prefix/include" -Wall -Wextra -Wpedantic -Wshadow -Wconversion \
    -Wsign-conversion -Werror -fsyntax-only "$tmp/header.cpp" ||
    fail "$(basename "$header") does not compile on its own without warnings"
done

# The command, whose modules are installed in lib/csgray/ (the build's own
# are still there to be found: the loader's log says which was loaded).
"$tmp/prefix/bin/csgray" --version >/dev/null || fail "the installed csgray does not run"
LD_DEBUG=files "$tmp/prefix/bin/csgray" export "$source/examples/primitives.lua" \
  -o "$tmp/primitives.stl" >"$tmp/export.log" 2>&1 ||
  { cat "$tmp/export.log" >&2; fail "the installed csgray cannot export"; }
grep -q "file=$tmp/prefix/.*/csgray/libcsgray_mesh_tools.so .*dynamically loaded" "$tmp/export.log" ||
  fail "the installed csgray did not load its installed module"

# Without its installed modules it fails rather than load the build's,
# which may be of another version.
mv "$tmp/prefix/lib/csgray" "$tmp/modules"
if "$tmp/prefix/bin/csgray" render "$source/examples/primitives.lua" -o "$tmp/no.jpg" \
  --size 32x24 >"$tmp/no_module.log" 2>&1; then
  fail "the installed csgray wrote a JPEG without its installed image module"
fi
grep -q "cannot load csgray's libcsgray_image_formats.so" "$tmp/no_module.log" ||
  { cat "$tmp/no_module.log" >&2; fail "no message for the missing module"; }
mv "$tmp/modules" "$tmp/prefix/lib/csgray"

"$cmake" -S "$source/examples/cpp" -B "$tmp/build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_PREFIX_PATH="$tmp/prefix" >"$tmp/configure.log" 2>&1 ||
  { cat "$tmp/configure.log" >&2; fail "examples/cpp does not configure"; }
"$cmake" --build "$tmp/build" >"$tmp/build.log" 2>&1 ||
  { cat "$tmp/build.log" >&2; fail "examples/cpp does not build"; }
mkdir "$tmp/out"
"$tmp/build/part" "$tmp/out" >"$tmp/out.log" || fail "the example failed"
cat "$tmp/out.log"
grep -q "^rendered $tmp/out/part.png" "$tmp/out.log" || fail "no line for the image"
grep -q "^exported $tmp/out/part.stl" "$tmp/out.log" || fail "no line for the mesh"

# The PNG: its signature, and its size in the IHDR chunk (big-endian).
png=$tmp/out/part.png
[ -s "$png" ] || fail "no image"
[ "$(od -An -c -j1 -N3 "$png" | tr -d ' ')" = PNG ] || fail "part.png is not a PNG file"
size=$(od -An -tu1 -j16 -N8 "$png" |
  awk '{ printf "%dx%d", (($1 * 256 + $2) * 256 + $3) * 256 + $4, (($5 * 256 + $6) * 256 + $7) * 256 + $8 }')
[ "$size" = 640x480 ] || fail "part.png is $size, not 640x480"

# The STL, read back through csgray.pc.
pc=$(find "$tmp/prefix" -name csgray.pc)
[ -n "$pc" ] || fail "csgray.pc was not installed"
export PKG_CONFIG_PATH
PKG_CONFIG_PATH=$(dirname "$pc")
libdir=$(pkg-config --variable=libdir csgray)
# shellcheck disable=SC2046
"$cxx" -std=c++17 $(pkg-config --cflags csgray) "$source/tests/api/install_check.cpp" -o "$tmp/check" \
  $(pkg-config --libs csgray) -Wl,-rpath,"$libdir" || fail "cannot build with pkg-config"
read_back=$("$tmp/check" "$tmp/out/part.stl") || fail "cannot read part.stl back"
triangles=${read_back% *} volume=${read_back#* }
[ "$triangles" -gt 0 ] || fail "part.stl has no triangles"
# The plate 40·30·8 less its four corners' (4 − π)·4²·8, less two holes
# π·4²·8, plus the half of the ball (radius 6) above it: 9600 − 512 +
# 128π − 256π + 144π. The export lies within 0.01 of the surface: well
# within 0.5 % of that.
awk -v v="$volume" 'BEGIN {
  exact = 9088 + 16 * atan2(0, -1)
  if (v < exact * 0.995 || v > exact * 1.005) { printf "volume %g, not %g\n", v, exact; exit 1 }
}' || fail "part.stl has the wrong volume"
echo "install_test: $triangles triangles, volume $volume"
