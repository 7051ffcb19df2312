#include "view/view_routes.h"

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "check/check_report.h"
#include "raytrace/renderer.h"
#include "view/json_text.h"
#include "view/view_frame.h"
#include "view/view_state_json.h"

namespace csgray::detail {

namespace {

constexpr auto kLongPoll = std::chrono::seconds(20);

ViewReply line(int status, const std::string& text) {
  ViewReply reply;
  reply.status = status;
  reply.body = text + "\n";
  return reply;
}

ViewReply json(std::string body) {
  return {200, std::move(body), "application/json", {{"Cache-Control", "no-store"}}};
}

// The one value of a query parameter; throws std::invalid_argument.
std::string parameter(const std::multimap<std::string, std::string>& query,
                      const std::string& key) {
  if (query.count(key) != 1) throw std::invalid_argument(key + " must be given once");
  return query.find(key)->second;
}

double numberParameter(const std::multimap<std::string, std::string>& query,
                       const std::string& key) {
  const std::string text = parameter(query, key);
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0') throw std::invalid_argument(key + " must be a number");
  return value;
}

std::string pickJson(const PickResult& pick) {
  if (!pick.hit) return "{\"hit\":false}";
  return "{\"hit\":true,\"point\":" + jsonVector(pick.point) +
         ",\"normal\":" + jsonVector(pick.normal) + ",\"kind\":" + jsonString(pick.kind) +
         ",\"source\":" + jsonString(pick.source) + "}";
}

// The name a download is offered under: the script's, with the format's
// extension, in characters that need no quoting in a header.
std::string downloadName(const std::string& script, const std::string& format) {
  std::string stem = std::filesystem::path(script).stem().string();
  for (char& c : stem)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '_';
  return (stem.empty() ? "part" : stem) + "." + format;
}

std::string jobJson(const JobStatus& job, bool stale, const std::string& script) {
  std::string body =
      "{\"id\":" + std::to_string(job.id) + ",\"kind\":" + jsonString(job.kind) +
      ",\"format\":" + jsonString(job.format) + ",\"stage\":" + jsonString(job.stage) +
      ",\"running\":" + (job.running ? "true" : "false") + ",\"error\":" + jsonString(job.error) +
      ",\"stale\":" + (stale ? "true" : "false");
  if (job.kind == "export" && job.stage == "done")
    body += ",\"bytes\":" + std::to_string(job.bytes) +
            ",\"name\":" + jsonString(downloadName(script, job.format)) +
            ",\"file\":\"/job/file?id=" + std::to_string(job.id) + "\"";
  if (job.report)
    body += ",\"report\":" + checkReportJson(*job.report, script) +
            ",\"text\":" + jsonString(checkReportText(*job.report, script));
  return body + "}";
}

}  // namespace

ViewReply ViewRoutes::job(const std::string& method, const std::string& path,
                          const std::multimap<std::string, std::string>& query) {
  const std::string& script = session_.script();
  if (!jobs_) return line(400, "export and check are not available here");
  const SessionState state = session_.state();
  if (method == "POST") {
    if (!state.scene) return line(409, "there is no part to " + path.substr(1) + " yet");
    if (!state.error.empty()) return line(409, "the script has an error; fix it first");
    try {
      if (path == "/export")
        jobs_->startExport(state.scene, state.version, state.outdated, script,
                           parameter(query, "format"));
      else
        jobs_->startCheck(state.scene, state.version, state.outdated, script);
    } catch (const JobBusy& e) {
      return line(409, e.what());
    }
    const JobStatus started = jobs_->status();
    ViewReply reply = json(jobJson(started, false, script));
    reply.status = 202;
    return reply;
  }
  const JobStatus status = jobs_->status();
  const bool stale = status.id != 0 && status.version != state.version;
  if (path == "/job") return json(jobJson(status, stale, script));
  // GET /job/file
  const double id = numberParameter(query, "id");
  if (!(id >= 1.0)) throw std::invalid_argument("id must be a job's number");
  const std::optional<std::string> bytes = jobs_->file(std::uint64_t(id));
  if (!bytes) return line(404, "no exported file of job " + parameter(query, "id"));
  if (stale) return line(409, "the part changed since this export; export it again");
  return {200,
          *bytes,
          status.format == "stl" ? "model/stl" : "model/3mf",
          {{"Cache-Control", "no-store"},
           {"Content-Disposition",
            "attachment; filename=\"" + downloadName(script, status.format) + "\""}}};
}

ViewReply ViewRoutes::handle(const std::string& method, const std::string& path,
                             const std::multimap<std::string, std::string>& query) {
  try {
    const std::string& script = session_.script();
    if (method == "GET" && path == "/scene") return json(stateJson(session_.state(), script));
    if (method == "GET" && path == "/wait") {
      const double version = numberParameter(query, "version");
      if (!(version >= 0.0)) throw std::invalid_argument("version must be a number >= 0");
      return json(stateJson(session_.waitForChange(std::uint64_t(version), kLongPoll), script));
    }
    if (method == "GET" && path == "/frame") {
      const FrameRequest frame = parseFrameRequest(query);
      const std::uint64_t version = session_.state().version;
      try {
        return {200,
                session_.frame(frame),
                "image/png",
                {{"Cache-Control", "no-store"}, {"X-Csgray-Version", std::to_string(version)}}};
      } catch (const RenderCancelled&) {
        return line(409, "superseded by a newer frame");
      }
    }
    if (method == "GET" && path == "/pick") {
      const FrameRequest frame = parseFrameRequest(query);
      return json(
          pickJson(session_.pick(frame, numberParameter(query, "x"), numberParameter(query, "y"))));
    }
    if (method == "POST" && path == "/define") {
      const std::string name = parameter(query, "name");
      std::optional<std::string> value;
      if (query.count("value")) value = parameter(query, "value");
      if (std::string refused = session_.define(name, value); !refused.empty())
        return line(400, refused);
      return json(stateJson(session_.state(), script));
    }
    if ((method == "POST" && (path == "/export" || path == "/check")) ||
        (method == "GET" && (path == "/job" || path == "/job/file")))
      return job(method, path, query);
    if (method == "POST" && path == "/reload") {
      session_.reload();
      return json(stateJson(session_.state(), script));
    }
    return line(404, "no such page: " + path);
  } catch (const std::invalid_argument& e) {
    return line(400, e.what());
  } catch (const std::exception& e) {
    return line(500, e.what());
  }
}

}  // namespace csgray::detail
