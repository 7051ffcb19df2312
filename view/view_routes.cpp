#include "view/view_routes.h"

#include <cstdlib>
#include <stdexcept>

#include "raytrace/renderer.h"
#include "view/json_text.h"
#include "view/view_frame.h"
#include "view/view_state_json.h"

namespace csgray::detail {

namespace {

constexpr auto kLongPoll = std::chrono::seconds(20);

ViewReply line(int status, const std::string& text) { return {status, text + "\n"}; }

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

}  // namespace

ViewReply ViewRoutes::handle(const std::string& method, const std::string& path,
                             const std::multimap<std::string, std::string>& query) {
  try {
    const std::string& script = session_.script();
    if (method == "GET" && path == "/scene") return json(stateJson(session_.state(), script));
    if (method == "GET" && path == "/wait") {
      const double version = numberParameter(query, "version");
      if (!(version >= 0.0)) throw std::invalid_argument("version must be a number");
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
