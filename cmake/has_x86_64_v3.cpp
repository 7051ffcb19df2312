// Run at configure time (CMakeLists.txt, CSGRAY_ARCH=auto): exits 0 if the
// processor that builds can run x86-64-v3 code (AVX2, FMA, BMI2, ...).
int main() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("x86-64-v3") ? 0 : 1;
}
