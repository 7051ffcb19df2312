// Reads a mesh file with the installed csgray library and prints its
// triangle count and volume: install_test.sh builds it with pkg-config, so
// that csgray.pc is tried as a user would use it.
#include <csgray/csgray.h>

#include <cstdio>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: install_check MESH\n");
    return 2;
  }
  try {
    const csgray::Mesh mesh = csgray::readMesh(argv[1]);
    std::printf("%zu %.9g\n", mesh.triangles.size(), mesh.volume());
  } catch (const csgray::Error& e) {
    std::fprintf(stderr, "install_check: %s\n", e.what());
    return 1;
  }
  return 0;
}
