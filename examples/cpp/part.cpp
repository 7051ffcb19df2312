// A plate with rounded corners and two holes, swept from its 2D outline,
// and a ball on top, made with the csgray library,
// rendered to part.png and exported to part.stl in the folder given (the
// current one by default), the export stopped should it take a minute.
#include <csgray/csgray.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <future>
#include <string>

int main(int argc, char** argv) {
  const std::string folder = argc > 1 ? argv[1] : ".";
  try {
    using csgray::Region;
    using csgray::Solid;
    // A 40 × 30 outline centred on the origin, its corners rounded with
    // radius 4, less two holes of radius 4, swept 8 up (from −4 to 4); a
    // ball of radius 6 whose centre is on the plate's top face.
    const Region outline = Region::rectangle({32, 22}, true).offset(4);
    const Region hole = Region::circle(4);
    const Region profile = outline - hole.translate({-12, 0}) - hole.translate({12, 0});
    csgray::ExtrudeOptions centred;
    centred.center = true;
    const Solid plate = Solid::linearExtrude(profile, 8, centred);
    const Solid ball = Solid::sphere(6).translate({0, 0, 4});
    csgray::Material steel;
    steel.color = {0.55, 0.6, 0.7};
    steel.specular = 0.4;
    const Solid part = (plate + ball).material(steel);

    csgray::Scene scene(part);
    scene.add(csgray::Surface::plane({0, 0, 1}, -4));  // a floor under the plate
    csgray::RenderOptions options;
    options.width = 640;
    options.height = 480;
    const csgray::Image image = csgray::render(scene, options);
    csgray::writeImage(image, folder + "/part.png");
    std::printf("rendered %s/part.png (%d x %d pixels)\n", folder.c_str(), image.width,
                image.height);

    // The export on a thread of its own, given a minute: past that the
    // flag stops it, and get() throws Error with ErrorCode::Cancelled (a
    // program's Stop button would set the same flag).
    std::atomic<bool> stop{false};
    csgray::ExportOptions exportOptions;
    exportOptions.cancel = &stop;
    std::future<csgray::Mesh> exporting =
        std::async(std::launch::async, [&] { return csgray::exportMesh(part, exportOptions); });
    if (exporting.wait_for(std::chrono::minutes(1)) == std::future_status::timeout) stop = true;
    const csgray::Mesh mesh = exporting.get();
    csgray::writeMesh(mesh, folder + "/part.stl");
    std::printf("exported %s/part.stl (%zu triangles, volume %.2f; exact %.2f)\n", folder.c_str(),
                mesh.triangles.size(), mesh.volume(), part.volume());
  } catch (const csgray::Error& e) {
    std::fprintf(stderr, "part: %s error: %s\n", csgray::errorCodeName(e.code()), e.what());
    return 1;
  }
  return 0;
}
