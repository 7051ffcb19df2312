#!/bin/bash
# The layers of docs/architecture.md, held against the code: a folder's
# files include only headers of their own layer and of the layers below
# it, each third-party library is included only where the architecture
# puts it, and the public headers include only each other and the
# standard library.
#   layers_test.sh SOURCE_DIR
set -u
cd "$1" || exit 2

# Bottom to top.
layers=(engine tessellation profile primitives scene raytrace io openscad export meshio check script view api cli)
rank() {
  local i
  for i in "${!layers[@]}"; do [[ ${layers[$i]} == "$1" ]] && echo "$i" && return; done
  echo -1
}

failures=0
fail() {
  echo "layers_test: $*"
  failures=$((failures + 1))
}

for layer in "${layers[@]}"; do
  own=$(rank "$layer")
  while IFS= read -r file; do
    while IFS= read -r included; do
      target=${included%%/*}
      [[ $target == csgray ]] && target=api  # include/csgray/
      below=$(rank "$target")
      if ((below < 0)); then
        fail "$file includes \"$included\", which is in no layer"
      elif ((below > own)); then
        fail "$file ($layer) includes \"$included\" of the layer above it ($target)"
      fi
    done < <(sed -n 's/^#include "\([^"]*\/[^"]*\)".*/\1/p' "$file")
  done < <(find "$layer" -name '*.h' -o -name '*.cpp')
done

# Where each dependency may be included: a pattern of the #include line,
# and the paths (extended regular expression) allowed to hold it.
check_dependency() {
  local pattern=$1 allowed=$2 name=$3 file
  while IFS= read -r file; do
    [[ $file =~ $allowed ]] || fail "$file includes $name, which belongs in ${allowed//[\\^$]/}"
  done < <(grep -rlE "^#include [<\"]($pattern)" "${layers[@]}" include --include='*.h' --include='*.cpp')
}
check_dependency 'CGAL/' '^(export|profile|primitives)/cgal/' CGAL
check_dependency 'OpenMesh/|lib3mf' '^meshio/' 'OpenMesh or lib3MF'
check_dependency 'OpenImageIO/' '^io/image_formats_module\.cpp$' OpenImageIO
check_dependency 'lua\.|lauxlib|lualib' '^script/' Lua
check_dependency 'ft2build|hb[.-]|fontconfig/' '^profile/glyph_outlines\.cpp$' 'FreeType, HarfBuzz or fontconfig'
check_dependency 'httplib' '^view/view_server\.cpp$' cpp-httplib

# The public headers: each other and the standard library, nothing else.
while IFS= read -r line; do
  [[ $line =~ ^#include\ \"csgray/ || $line =~ ^#include\ \<[a-z_]+\> ]] ||
    fail "a public header has $line"
done < <(grep -h '^#include' include/csgray/*.h)

if ((failures > 0)); then
  echo "layers_test: $failures rule(s) broken (docs/architecture.md)"
  exit 1
fi
echo "layers_test: every include keeps to the layers"
