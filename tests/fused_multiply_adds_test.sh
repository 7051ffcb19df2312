#!/bin/bash
# The x86-64-v3 build's promise (CMakeLists.txt): no fused multiply-adds
# but the std::fma calls the code writes, which are scalar. A packed one
# (vfmaddsub…pd, vfmadd…pd, …) is the compiler's own fusing of products
# and sums, which moves results off the portable build's in the last bits.
#   fused_multiply_adds_test.sh BINARY...
set -u
failures=0
for binary in "$@"; do
  if ! listing=$(objdump -d --no-show-raw-insn "$binary"); then
    echo "cannot disassemble $binary"
    exit 2
  fi
  # The mnemonic's last letters name the operands: p for packed, s for scalar.
  fused=$(grep -oE '\svfn?m(add|sub)(sub|add)?[0-9]*p[sd]\s' <<<"$listing" | sort | uniq -c)
  if [[ -n $fused ]]; then
    echo "$binary: packed fused multiply-adds the code does not write:"
    echo "$fused"
    failures=$((failures + 1))
  fi
  # The scalar ones the code writes (std::fma) are there: the listing is read.
  if ! grep -qE '\svfn?m(add|sub)[0-9]*sd\s' <<<"$listing"; then
    echo "$binary: not one of the scalar std::fma the code writes: is this the v3 build?"
    failures=$((failures + 1))
  fi
done
exit $((failures > 0))
