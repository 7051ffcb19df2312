// Between the web server (view_server.h, in a module of its own with
// cpp-httplib) and what answers its requests (view_routes.h, with the
// script and the renderer, in the executable): an interface of virtual
// functions only, so that the module needs none of the executable's code.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace csgray::detail {

struct ViewReply {
  int status = 200;
  std::string body;
  std::string type = "text/plain; charset=utf-8";
  std::vector<std::pair<std::string, std::string>> headers;
};

class ViewService {
 public:
  virtual ~ViewService() = default;
  // Answers "GET /scene", "POST /define", ... (view_server.h lists them);
  // never throws: a request it cannot take gets a 400 and one line.
  virtual ViewReply handle(const std::string& method, const std::string& path,
                           const std::multimap<std::string, std::string>& query) = 0;
  // Ends the long polls: the server is stopping.
  virtual void shutdown() = 0;
};

// The web server, as the executable sees it.
class HttpServer {
 public:
  virtual ~HttpServer() = default;
  virtual int port() const = 0;
  // "http://127.0.0.1:PORT/"
  virtual std::string url() const = 0;
  // Serves on this thread until stop().
  virtual void run() = 0;
  // Serves on a thread of its own (the tests).
  virtual void start() = 0;
  // Ends serving; safe from any thread.
  virtual void stop() = 0;
};

// 127.0.0.1 (any 127.x.y.z), ::1 or localhost.
inline bool isLoopback(const std::string& address) {
  return address == "localhost" || address == "::1" || address.starts_with("127.");
}

}  // namespace csgray::detail
