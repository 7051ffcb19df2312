// csgray view's server, in this process on 127.0.0.1, asked as the page
// asks: frames as PNG files of the size asked for, what lies under a
// pixel, reloads when the script is written, a broken script's error with
// its line while the last good scene stays, the customizer's values, and
// requests it refuses.
#include "view/view_server.h"

#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <httplib.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <future>
#include <thread>

#include "check/part_check.h"
#include "io/scratch_folder.h"
#include "meshio/part_file_bytes.h"
#include "raytrace/renderer.h"
#include "view/file_watcher.h"
#include "view/view_frame.h"
#include "view/view_routes.h"
#include "view/view_session.h"

namespace csgray::detail {
namespace {

namespace fs = std::filesystem;

// A script in a folder of its own, the session and watcher as `csgray
// view` makes them, and a client of the server.
class ViewServerTest : public testing::Test {
 protected:
  // The tools of the export and check buttons, as the command line gives them.
  static PartTools meshTools() {
    PartTools tools;
    tools.meshFile = [](const Scene& scene, const std::string& script, const std::string& format,
                        const std::function<void(const std::string&)>& stage) {
      return partFileBytes(scene, script, format, 0.01, stage, [](const std::string&) {});
    };
    tools.check = [](const Scene& scene, const std::string& script) {
      CheckOptions options;
      options.samples = 2000;
      options.grid = 32;
      return checkPrintedPart(scene, script, options, [](const std::string&) {});
    };
    return tools;
  }
  void start(const std::string& source, PartTools tools = meshTools()) {
    folder_ = csgray::test::scratchPathFor("csgray_view_test_");
    fs::create_directories(folder_);
    script_ = (folder_ / "part.lua").string();
    write(source);
    session_ = std::make_unique<ViewSession>(script_, ScriptOptions{}, 2);
    watcher_ = std::make_unique<FileWatcher>(
        [this] {
          session_->reload();
          watcher_->watch(session_->state().files);
        },
        std::chrono::milliseconds(20));
    watcher_->watch(session_->state().files);
    jobs_ = std::make_unique<ViewJobs>(std::move(tools));
    routes_ = std::make_unique<ViewRoutes>(*session_, jobs_.get());
    server_ = makeViewServer(*routes_, "127.0.0.1", 0);
    server_->start();
    client_ = std::make_unique<httplib::Client>("127.0.0.1", server_->port());
    client_->set_read_timeout(60, 0);
  }
  void TearDown() override {
    client_.reset();
    server_.reset();
    routes_.reset();
    jobs_.reset();
    // The watcher's thread may be running its callback, which calls
    // watcher_->watch: destroy the watcher (its destructor joins that
    // thread) while watcher_ still points at it, not through reset(),
    // which clears the pointer first.
    if (watcher_) {
      watcher_.get_deleter()(watcher_.get());
      (void)watcher_.release();
    }
    session_.reset();
    fs::remove_all(folder_);
  }
  // Written as editors do: a new file renamed over the old one.
  void write(const std::string& source) {
    const fs::path temporary = folder_ / ".part.lua.swp";
    std::ofstream(temporary) << source;
    fs::rename(temporary, script_);
  }
  std::string get(const std::string& path, int status = 200) {
    auto response = client_->Get(path.c_str());
    EXPECT_TRUE(response) << path;
    if (!response) return {};
    EXPECT_EQ(response->status, status) << path << ": " << response->body;
    return response->body;
  }
  // The state once a run after `version` is done.
  std::string waitAfter(std::uint64_t version) {
    return get("/wait?version=" + std::to_string(version));
  }

  fs::path folder_;
  std::string script_;
  std::unique_ptr<ViewSession> session_;
  std::unique_ptr<FileWatcher> watcher_;
  std::unique_ptr<ViewJobs> jobs_;
  std::unique_ptr<ViewRoutes> routes_;
  std::unique_ptr<HttpServer> server_;
  std::unique_ptr<httplib::Client> client_;
};

// The width and height of a PNG file's IHDR chunk.
std::pair<int, int> pngSize(const std::string& png) {
  EXPECT_GE(png.size(), 24u);
  EXPECT_EQ(png.substr(0, 8), "\x89PNG\r\n\x1a\n");
  auto be = [&](std::size_t at) {
    return int((std::uint8_t(png[at]) << 24) | (std::uint8_t(png[at + 1]) << 16) |
               (std::uint8_t(png[at + 2]) << 8) | std::uint8_t(png[at + 3]));
  };
  return {be(16), be(20)};
}

const std::string kFront = "camera=0,-50,0,0,0,0,0,0,1";

TEST_F(ViewServerTest, FramesArePngFilesOfThePassSize) {
  start("return box{size={10, 10, 10}, center=true}\n");
  EXPECT_EQ(pngSize(get("/frame?size=64x48&pass=1")), std::make_pair(64, 48));
  EXPECT_EQ(pngSize(get("/frame?size=64x48&pass=0")), std::make_pair(16, 12));
  EXPECT_EQ(pngSize(get("/frame?size=64x48&pass=2&" + kFront + "&fov=30")), std::make_pair(64, 48));
  EXPECT_EQ(pngSize(get("/frame?size=30x20&" + kFront + "&ortho=40")), std::make_pair(30, 20));
  // Another camera, another picture.
  EXPECT_NE(get("/frame?size=32x32&" + kFront + "&fov=45"),
            get("/frame?size=32x32&camera=50,0,50,0,0,0,0,0,1&fov=45"));
  EXPECT_NE(get("/").find("<canvas"), std::string::npos);
  EXPECT_NE(get("/view.js").find("/frame?"), std::string::npos);
}

TEST_F(ViewServerTest, PickNamesThePointThePrimitiveAndItsLine) {
  start(
      "local base = box{size={10, 10, 10}, center=true}\n"
      "return base - sphere{r=2}:translate(0, -5, 0)\n");
  // Through the centre of the front face: into the sphere's dent, 2 deep.
  std::string hit = get("/pick?size=101x101&" + kFront + "&fov=30&x=50.5&y=50.5");
  EXPECT_NE(hit.find("\"hit\":true"), std::string::npos) << hit;
  EXPECT_NE(hit.find("\"point\":[0,-3,0]"), std::string::npos) << hit;
  EXPECT_NE(hit.find("\"kind\":\"sphere\""), std::string::npos) << hit;
  EXPECT_NE(hit.find("part.lua:2"), std::string::npos) << hit;
  // Beside the dent, on the box's face.
  std::string face = get("/pick?size=101x101&" + kFront + "&ortho=20&x=50.5&y=35.5");
  EXPECT_NE(face.find("\"kind\":\"box\""), std::string::npos) << face;
  EXPECT_NE(face.find("part.lua:1"), std::string::npos) << face;
  EXPECT_NE(face.find("\"normal\":[0,-1,0]"), std::string::npos) << face;
  EXPECT_EQ(get("/pick?size=101x101&" + kFront + "&ortho=20&x=1&y=1"), "{\"hit\":false}");
}

TEST_F(ViewServerTest, PickOnAnOpenSurfaceGivesTheNormalOfTheSideSeen) {
  // A square sheet in the plane y = 0, its faces wound to face +y, seen
  // from -y: the normal points back at the camera.
  start(
      "return scene{objects={mesh_surface{points={{-5, 0, -5}, {-5, 0, 5}, {5, 0, 5}, "
      "{5, 0, -5}}, faces={{0, 1, 2}, {0, 2, 3}}, smooth=false}}}\n");
  const std::string hit = get("/pick?size=101x101&" + kFront + "&ortho=20&x=60.5&y=40.5");
  EXPECT_NE(hit.find("\"kind\":\"mesh surface\""), std::string::npos) << hit;
  EXPECT_NE(hit.find("\"normal\":[0,-1,0]"), std::string::npos) << hit;
}

TEST_F(ViewServerTest, ASectionCutsThePartInTheFrameAndThePick) {
  start("return box{size={10, 10, 10}, center=true} - box{size={8, 8, 8}, center=true}\n");
  const std::string view = "size=101x101&" + kFront + "&ortho=20";
  const std::string cut = "&section=0,-2,0,0";  // the near half gone
  // The centre: the front face; cut, the cavity's back wall.
  EXPECT_NE(get("/pick?" + view + "&x=50.5&y=50.5").find("\"point\":[0,-5,0]"), std::string::npos);
  const std::string back = get("/pick?" + view + cut + "&x=50.5&y=50.5");
  EXPECT_NE(back.find("\"point\":[0,4,0]"), std::string::npos) << back;
  EXPECT_NE(back.find("\"kind\":\"box\""), std::string::npos) << back;
  // In the wall (x from 4 to 5): the cut face, facing the camera.
  const std::string wall = get("/pick?" + view + cut + "&x=73.5&y=50.5");
  EXPECT_NE(wall.find("\"kind\":\"section\""), std::string::npos) << wall;
  EXPECT_NE(wall.find("\"normal\":[0,-1,0]"), std::string::npos) << wall;
  EXPECT_NE(get("/frame?" + view), get("/frame?" + view + cut));
  // The same plane given by a normal whose length overflows a double.
  const std::string large = get("/pick?" + view + "&section=0,-1e308,0,0&x=50.5&y=50.5");
  EXPECT_NE(large.find("\"point\":[0,4,0]"), std::string::npos) << large;
  EXPECT_EQ(get("/frame?section=0,0,0,1", 400), "section's normal must not be zero\n");
  EXPECT_EQ(get("/frame?section=0,0,1", 400),
            "section must be 4 numbers: the plane's normal and offset\n");
}

TEST_F(ViewServerTest, GhostsAndHighlightsCanBeLeftOutOfTheFrame) {
  start(
      "local cutter = cylinder{r=2, h=12, center=true}:rotate(90, 0, 0):highlight()\n"
      "local bolt = sphere(2):translate(0, -10, 0):ghost()\n"
      "return box{size={10, 10, 10}, center=true} - cutter + bolt\n");
  const std::string state = get("/scene");
  EXPECT_NE(state.find("\"ghosts\":1,\"highlights\":1"), std::string::npos) << state;
  // The bounds are the model's: the ghost, reaching to y = -12, is no part.
  EXPECT_NE(state.find("\"bounds\":{\"lo\":[-5,-5,-5],\"hi\":[5,5,5]}"), std::string::npos)
      << state;
  // Through the middle from the front: the ghost's sphere, or without it
  // the highlighted cutter's hole through the box, seen to its end.
  const std::string view = "size=101x101&" + kFront + "&ortho=20&x=50.5&y=50.5";
  EXPECT_NE(get("/pick?" + view).find("\"point\":[0,-12,0]"), std::string::npos);
  EXPECT_EQ(get("/pick?" + view + "&ghosts=0"), "{\"hit\":false}");
  const std::string frame = "/frame?size=64x64&" + kFront + "&ortho=20";
  EXPECT_NE(get(frame), get(frame + "&highlights=0"));
  EXPECT_NE(get(frame), get(frame + "&ghosts=0"));
  EXPECT_EQ(get(frame + "&ghosts=0&highlights=0"), get(frame + "&highlights=0&ghosts=0"));
  EXPECT_EQ(get("/frame?ghosts=2", 400), "ghosts must be 0 or 1\n");
}

TEST_F(ViewServerTest, ExportsServeTheFileAsADownloadAndWriteNothingBesideTheScript) {
  start("return box(10)\n");
  auto response = client_->Post("/export?format=stl");
  ASSERT_TRUE(response);
  EXPECT_EQ(response->status, 202);
  EXPECT_NE(response->body.find("\"kind\":\"export\""), std::string::npos) << response->body;
  jobs_->waitIdle();
  const std::string job = get("/job");
  EXPECT_NE(job.find("\"stage\":\"done\""), std::string::npos) << job;
  EXPECT_NE(job.find("\"name\":\"part.stl\""), std::string::npos) << job;
  EXPECT_NE(job.find("\"file\":\"/job/file?id=1\""), std::string::npos) << job;
  response = client_->Get("/job/file?id=1");
  ASSERT_TRUE(response);
  EXPECT_EQ(response->status, 200);
  EXPECT_EQ(response->get_header_value("Content-Disposition"), "attachment; filename=\"part.stl\"");
  // A binary STL of a box: 80 bytes of header, the count, 12 triangles of 50 bytes.
  ASSERT_EQ(response->body.size(), 84u + 12u * 50u);
  EXPECT_EQ(std::uint8_t(response->body[80]), 12);
  EXPECT_EQ(client_->Post("/export?format=3mf")->status, 202);
  jobs_->waitIdle();
  response = client_->Get("/job/file?id=2");
  EXPECT_EQ(response->body.substr(0, 2), "PK");  // a 3MF file is a zip
  EXPECT_EQ(response->get_header_value("Content-Disposition"), "attachment; filename=\"part.3mf\"");
  // Not the older job's any more, nor one that never was.
  EXPECT_EQ(get("/job/file?id=1", 404), "no exported file of job 1\n");
  EXPECT_EQ(get("/job/file?id=x", 400), "id must be a number\n");
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(folder_))
    files.push_back(entry.path().filename());
  EXPECT_EQ(files, std::vector<fs::path>{"part.lua"});
  response = client_->Post("/export?format=obj");
  EXPECT_EQ(response->status, 400);
  EXPECT_EQ(response->body, "format must be stl or 3mf\n");
  EXPECT_EQ(client_->Post("/export")->body, "format must be given once\n");
}

TEST_F(ViewServerTest, TheCheckGivesItsReportWithTheWarningsPoints) {
  // The cut's top and bottom lie in the box's: coincident faces.
  start("return box(10) - box{size={5, 5, 10}}\n");
  EXPECT_EQ(client_->Post("/check")->status, 202);
  jobs_->waitIdle();
  const std::string job = get("/job");
  EXPECT_NE(job.find("\"stage\":\"done\""), std::string::npos) << job;
  EXPECT_NE(job.find("\"report\":{"), std::string::npos) << job;
  EXPECT_NE(job.find("\"kind\": \"coincident faces\""), std::string::npos) << job;
  EXPECT_NE(job.find("\"at\": ["), std::string::npos) << job;
  EXPECT_NE(job.find("\"text\":\""), std::string::npos) << job;
  EXPECT_EQ(job.find("\"file\""), std::string::npos) << job;
}

TEST_F(ViewServerTest, OneJobAtATimeAndANewRunMakesItsResultStale) {
  // A check that waits to be let go.
  std::promise<void> letGo;
  std::shared_future<void> go = letGo.get_future().share();
  PartTools tools = meshTools();
  tools.check = [go](const Scene&, const std::string&) {
    go.wait();
    return CheckReport{};
  };
  start("return box(10)\n", tools);
  EXPECT_EQ(client_->Post("/check")->status, 202);
  auto busy = client_->Post("/export?format=stl");
  EXPECT_EQ(busy->status, 409);
  EXPECT_EQ(busy->body, "a check is running; wait for it to end\n");
  EXPECT_NE(get("/job").find("\"running\":true"), std::string::npos);
  const std::uint64_t version = session_->state().version;
  write("return box(12)\n");
  waitAfter(version);
  letGo.set_value();
  jobs_->waitIdle();
  const std::string job = get("/job");
  EXPECT_NE(job.find("\"stale\":true"), std::string::npos) << job;
  // An export of the new part, then a run: its file is no longer served.
  EXPECT_EQ(client_->Post("/export?format=stl")->status, 202);
  jobs_->waitIdle();
  EXPECT_EQ(client_->Get("/job/file?id=2")->status, 200);
  client_->Post("/reload");
  EXPECT_EQ(get("/job/file?id=2", 409), "the part changed since this export; export it again\n");
  // A broken script: nothing to export.
  const std::uint64_t good = session_->state().version;
  write("return box(\n");
  waitAfter(good);
  EXPECT_EQ(client_->Post("/check")->body, "the script has an error; fix it first\n");
}

// An export of a part that takes long (a ball drilled by 60 rods that
// cross at its centre: 5.8 s on 2 cores), then a save: the job stops
// at its next step, its result no longer wanted, and the server is free
// for the new part at once (left running, the job ends "done").
TEST_F(ViewServerTest, ANewRunStopsTheJobOfTheOldPart) {
  start(
      "local s = sphere(20)\n"
      "for i = 1, 60 do\n"
      "  s = s - cylinder{r = 1.5, h = 60, center = true}:rotate(i * 37, i * 13, 0)\n"
      "end\n"
      "return s\n");
  EXPECT_EQ(client_->Post("/export?format=stl")->status, 202);
  const std::uint64_t version = session_->state().version;
  write("return box(10)\n");
  waitAfter(version);
  jobs_->waitIdle();
  std::string job = get("/job");
  EXPECT_NE(job.find("\"stage\":\"stopped\""), std::string::npos) << job;
  EXPECT_NE(job.find("\"stale\":true"), std::string::npos) << job;
  EXPECT_NE(job.find("\"error\":\"\""), std::string::npos) << job;
  EXPECT_EQ(get("/job/file?id=1", 404), "no exported file of job 1\n");
  // The new part's export runs to its end.
  EXPECT_EQ(client_->Post("/export?format=stl")->status, 202);
  jobs_->waitIdle();
  job = get("/job");
  EXPECT_NE(job.find("\"stage\":\"done\""), std::string::npos) << job;
  EXPECT_EQ(client_->Get("/job/file?id=2")->status, 200);
}

TEST_F(ViewServerTest, ReloadsWhenTheScriptIsWrittenAndKeepsTheLastGoodSceneOnAnError) {
  start("return box{size={10, 10, 10}}\n");
  std::string state = get("/scene");
  EXPECT_NE(state.find("\"hi\":[10,10,10]"), std::string::npos) << state;
  const std::uint64_t first = session_->state().version;
  write("return sphere{r=3}\n");
  state = waitAfter(first);
  EXPECT_NE(state.find("\"lo\":[-3,-3,-3]"), std::string::npos) << state;
  EXPECT_NE(state.find("\"error\":\"\""), std::string::npos) << state;
  const std::uint64_t second = session_->state().version;
  write("local r = 3\nreturn sphere{r=r, h=2}\n");
  state = waitAfter(second);
  EXPECT_NE(state.find("part.lua:2:"), std::string::npos) << state;
  // The sphere is still what the page shows, and renders.
  EXPECT_NE(state.find("\"lo\":[-3,-3,-3]"), std::string::npos) << state;
  EXPECT_EQ(pngSize(get("/frame?size=20x10")), std::make_pair(20, 10));
}

TEST(ViewSession, WatchesTheFilesTheScriptReads) {
  const fs::path folder =
      fs::temp_directory_path() / ("csgray_view_files_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  std::ofstream(folder / "part.lua") << "local t = image_texture{file='wood.png'}\n"
                                        "return box(1) + import_csg{file='nut.csg'}\n";
  std::ofstream(folder / "wood.png") << "x";
  std::ofstream(folder / "nut.csg") << "cube(size = [1, 1, 1], center = false);\n";
  // The loader stands in for the command line's; the session notes every
  // file the script names, an OpenSCAD file too.
  ScriptOptions options;
  options.loadImage = [](const std::string&) { return TextureImage{1, 1, {0.5f, 0.5f, 0.5f}}; };
  ViewSession session((folder / "part.lua").string(), options, 1);
  const std::vector<std::string> files = session.state().files;
  ASSERT_EQ(files.size(), 3u) << session.state().error;
  for (const char* name : {"part.lua", "wood.png", "nut.csg"})
    EXPECT_EQ(std::count_if(files.begin(), files.end(),
                            [&](const std::string& f) { return f.ends_with(name); }),
              1)
        << name;
  std::atomic<int> changes = 0;
  FileWatcher watcher([&] { ++changes; }, std::chrono::milliseconds(20));
  watcher.watch(files);
  std::ofstream(folder / "other.txt") << "not watched";
  std::ofstream(folder / "wood.png") << "y";
  for (int i = 0; i < 500 && changes == 0; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_EQ(changes, 1);
  fs::remove_all(folder);
}

TEST_F(ViewServerTest, CustomizerValuesRunTheScriptAgain) {
  start(
      "width = 40 -- [10:100] the width\n"
      "size = {1, 2, 3} -- [1:10]\n"
      "return box{size={width, size[2], size[3]}}\n");
  std::string state = get("/scene");
  EXPECT_NE(state.find("{\"name\":\"width\",\"line\":1,\"kind\":\"number\",\"value\":40,"
                       "\"default\":40,\"min\":10,\"max\":100,\"step\":0,"
                       "\"description\":\"the width\"}"),
            std::string::npos)
      << state;
  auto post = [&](const std::string& query) { return client_->Post(query.c_str()); };
  auto response = post("/define?name=width&value=20");
  ASSERT_TRUE(response);
  EXPECT_EQ(response->status, 200);
  EXPECT_NE(response->body.find("\"hi\":[20,2,3]"), std::string::npos) << response->body;
  EXPECT_NE(response->body.find("\"value\":20"), std::string::npos) << response->body;
  response = post("/define?name=size&value=%7B1%2C5%2C7%7D");
  EXPECT_NE(response->body.find("\"hi\":[20,5,7]"), std::string::npos) << response->body;
  // Refused: nothing changes.
  response = post("/define?name=width&value=500");
  EXPECT_EQ(response->status, 400);
  EXPECT_EQ(response->body, "-D width=500: width must be from 10 to 100 (" + script_ + ":1)\n");
  EXPECT_NE(get("/scene").find("\"hi\":[20,5,7]"), std::string::npos);
  // Without a value: the script's default again.
  response = post("/define?name=width");
  EXPECT_NE(response->body.find("\"hi\":[40,5,7]"), std::string::npos) << response->body;
}

TEST_F(ViewServerTest, RefusesWhatItCannotTakeWithOneLine) {
  start("return box(1)\n");
  EXPECT_EQ(get("/frame?size=abc", 400), "size must be WIDTHxHEIGHT, e.g. 800x600\n");
  EXPECT_EQ(get("/frame?size=99999x2", 400), "size must be 1 to 4096 per side\n");
  EXPECT_EQ(get("/frame?camera=1,2,3", 400), "camera must be 9 numbers: eye, target and up\n");
  EXPECT_EQ(get("/frame?camera=0,0,0,0,0,0,0,0,1", 400),
            "camera: eye and look_at are the same point\n");
  EXPECT_EQ(get("/frame?camera=0,-5,0,0,0,0,0,-1,0", 400),
            "camera: up must not be parallel to the view direction\n");
  // Numbers whose squares overflow: said as they are.
  EXPECT_EQ(get("/frame?camera=1e308,0,0,-1e308,0,0,0,0,1", 400),
            "camera: eye and look_at are too far apart\n");
  EXPECT_EQ(get("/frame?camera=1e300,0,0,0,0,0,0,0,1", 400),
            "camera: eye and look_at are too far apart\n");
  EXPECT_EQ(get("/frame?camera=1e-200,0,0,0,0,0,0,0,1", 400),
            "camera: eye and look_at are too close together\n");
  EXPECT_EQ(get("/frame?pass=7", 400), "pass must be 0, 1 or 2\n");
  EXPECT_EQ(get("/frame?" + kFront + "&fov=200", 400), "fov must be between 0 and 180 degrees\n");
  EXPECT_EQ(get("/frame?size=1x1&size=2x2", 400), "size is given twice\n");
  EXPECT_EQ(get("/pick?size=10x10&y=1", 400), "x must be given once\n");
  EXPECT_EQ(get("/pick?size=10x10&x=20&y=1", 400), "x and y must be within the frame's size\n");
  EXPECT_EQ(get("/wait?version=x", 400), "version must be a number\n");
  EXPECT_EQ(get("/wait?version=-1", 400), "version must be a number >= 0\n");
  EXPECT_EQ(get("/nothing", 404), "no such page: /nothing\n");
  auto response = client_->Post("/define");
  EXPECT_EQ(response->status, 400);
}

TEST_F(ViewServerTest, AnswersOnlyItsOwnAddress) {
  start("return box(1)\n");
  httplib::Headers rebound = {{"Host", "attacker.example:" + std::to_string(server_->port())}};
  auto response = client_->Get("/scene", rebound);
  ASSERT_TRUE(response);
  EXPECT_EQ(response->status, 403);
  httplib::Headers crossSite = {{"Origin", "http://attacker.example"}};
  response = client_->Post("/define?name=x&value=1", crossSite, "", "text/plain");
  EXPECT_EQ(response->status, 403);
  httplib::Headers local = {{"Host", "localhost:" + std::to_string(server_->port())}};
  EXPECT_EQ(client_->Get("/scene", local)->status, 200);
  EXPECT_EQ(server_->url(), "http://127.0.0.1:" + std::to_string(server_->port()) + "/");
  // Another loopback address, asked for, answers the URL it prints.
  const auto other = makeViewServer(*routes_, "127.0.0.2", 0);
  other->start();
  EXPECT_EQ(other->url(), "http://127.0.0.2:" + std::to_string(other->port()) + "/");
  httplib::Client otherClient("127.0.0.2", other->port());
  auto answer = otherClient.Get("/scene");
  ASSERT_TRUE(answer);
  EXPECT_EQ(answer->status, 200);
  other->stop();
  EXPECT_TRUE(isLoopback("127.0.0.1"));
  EXPECT_TRUE(isLoopback("::1"));
  EXPECT_TRUE(isLoopback("localhost"));
  EXPECT_FALSE(isLoopback("0.0.0.0"));
  EXPECT_FALSE(isLoopback("192.168.1.2"));
}

// The server's answer to a request written out byte for byte, as a
// client library would not write it.
std::string exchange(int port, const std::string& request) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  ::inet_pton(AF_INET, "127.0.0.1", &address.sin_addr);
  std::string answer;
  if (::connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) == 0 &&
      ::send(fd, request.data(), request.size(), 0) == static_cast<ssize_t>(request.size())) {
    char buffer[4096];
    for (ssize_t n; (n = ::recv(fd, buffer, sizeof buffer, 0)) > 0;) answer.append(buffer, n);
  }
  ::close(fd);
  return answer;
}

TEST_F(ViewServerTest, RefusesTwoHostsAndAPostWithoutALength) {
  start("return box(1)\n");
  const std::string host = "Host: 127.0.0.1:" + std::to_string(server_->port()) + "\r\n";
  // A proxy might read the second Host where this server reads the first.
  const std::string twice = exchange(server_->port(), "GET /scene HTTP/1.1\r\n" + host +
                                                          "Host: attacker.example\r\n"
                                                          "Connection: close\r\n\r\n");
  EXPECT_EQ(twice.rfind("HTTP/1.1 400", 0), 0u) << twice;
  EXPECT_NE(twice.find("a request may have one Host header only"), std::string::npos) << twice;
  // Its body would be read until the read timed out.
  const std::string endless =
      exchange(server_->port(), "POST /reload HTTP/1.1\r\n" + host + "Connection: close\r\n\r\n");
  EXPECT_EQ(endless.rfind("HTTP/1.1 411", 0), 0u) << endless;
  EXPECT_NE(endless.find("a POST needs a Content-Length header"), std::string::npos) << endless;
  const std::string once =
      exchange(server_->port(), "GET /scene HTTP/1.1\r\n" + host + "Connection: close\r\n\r\n");
  EXPECT_EQ(once.rfind("HTTP/1.1 200", 0), 0u) << once;
}

TEST(ViewSession, ANewerFrameCancelsTheOneInProgress) {
  const fs::path script =
      fs::temp_directory_path() / ("csgray_view_cancel_" + std::to_string(::getpid()) + ".lua");
  std::ofstream(script)
      << "local s = sphere(1)\nfor i = 1, 40 do s = s + sphere(1):translate(i * 0.1, 0, 0) end\n"
         "return s\n";
  ViewSession session(script.string(), {}, 1);
  FrameRequest large;
  large.width = large.height = 4096;
  large.pass = 2;
  std::atomic<bool> cancelled = false;
  std::thread slow([&] {
    try {
      session.frame(large);
    } catch (const RenderCancelled&) {
      cancelled = true;
    }
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  FrameRequest small;
  small.width = small.height = 8;
  EXPECT_FALSE(session.frame(small).empty());
  slow.join();
  EXPECT_TRUE(cancelled);
  fs::remove(script);
}

}  // namespace
}  // namespace csgray::detail
