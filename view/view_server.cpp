#include "view/view_server.h"

#include <httplib.h>
#include <sys/socket.h>

#include <chrono>
#include <thread>

#include "view/page_assets.h"

namespace csgray::detail {

namespace {

void reply(httplib::Response& response, int status, const std::string& line) {
  response.status = status;
  response.set_content(line + "\n", "text/plain; charset=utf-8");
}

class ViewServer final : public HttpServer {
 public:
  static constexpr int kThreads = 64;

  ViewServer(ViewService& service, const std::string& address, int port)
      : service_(service), address_(address) {
    // Frames, the long poll, picks and the page's own files at once; a
    // browser keeps a few connections open. Each connection holds a
    // thread while it sends its request or waits between requests: a
    // client that opens connections and sends half a request held all of
    // 16 threads for cpp-httplib's 5 s, and the page waited (20 such
    // connections: 8.5 s). Idle threads cost little; a connection that
    // sends nothing for 2 s is closed.
    server_.new_task_queue = [] { return new httplib::ThreadPool(kThreads); };
    server_.set_read_timeout(2, 0);
    server_.set_keep_alive_timeout(2);
    // A reply is written as headers, then body: with Nagle's algorithm the
    // body waits for the client's delayed ACK of the headers, 40 ms on
    // Linux, which halved the frames per second of a drag.
    server_.set_tcp_nodelay(true);
    server_.set_pre_routing_handler(
        [this](const httplib::Request& request, httplib::Response& response) {
          return refused(request, response) ? httplib::Server::HandlerResponse::Handled
                                            : httplib::Server::HandlerResponse::Unhandled;
        });
    for (const PageAsset& asset : pageAssets())
      server_.Get(asset.path == "/index.html" ? "/" : std::string(asset.path),
                  [asset](const httplib::Request&, httplib::Response& response) {
                    response.set_header("Cache-Control", "no-store");
                    response.set_content(asset.body.data(), asset.body.size(), asset.type.data());
                  });
    for (const char* path : {"/scene", "/wait", "/frame", "/pick", "/job", "/job/file"})
      server_.Get(path, [this](const httplib::Request& request, httplib::Response& response) {
        pass("GET", request, response);
      });
    for (const char* path : {"/define", "/reload", "/export", "/check"})
      server_.Post(path, [this](const httplib::Request& request, httplib::Response& response) {
        pass("POST", request, response);
      });
    server_.set_exception_handler(
        [](const httplib::Request&, httplib::Response& response, std::exception_ptr) {
          reply(response, 500, "the server failed on this request");
        });
    server_.set_error_handler([](const httplib::Request& request, httplib::Response& response) {
      if (response.body.empty())
        reply(response, response.status,
              response.status == 404 ? "no such page: " + request.path : "bad request");
    });
    // SO_REUSEADDR alone: a view started again at once takes its port back
    // from the last one's closing connections. cpp-httplib's default adds
    // SO_REUSEPORT, with which a second csgray view on the same port
    // listened beside the first, and the kernel sent the page's requests
    // to either part at random.
    server_.set_socket_options([](socket_t socket) {
      int yes = 1;
      setsockopt(socket, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof(yes));
    });
    port_ = port == 0 ? server_.bind_to_any_port(address)
                      : (server_.bind_to_port(address, port) ? port : -1);
    if (port_ <= 0)
      throw std::runtime_error("cannot listen on " + address + ":" + std::to_string(port) +
                               (port == 0 ? "" : " (is the port in use?)"));
  }

  ~ViewServer() override {
    stop();
    if (thread_.joinable()) thread_.join();
  }

  int port() const override { return port_; }
  std::string url() const override { return "http://" + ownHost() + "/"; }
  void run() override { server_.listen_after_bind(); }
  void start() override {
    thread_ = std::thread([this] { run(); });
    while (!server_.is_running()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  void stop() override {
    service_.shutdown();
    server_.stop();
  }

 private:
  // The Host a browser sends for url(): the address (an IPv6 one in
  // brackets) and the port.
  std::string ownHost() const {
    const std::string host =
        address_.find(':') != std::string::npos ? "[" + address_ + "]" : address_;
    return host + ":" + std::to_string(port_);
  }

  // Another site's page, or a name that rebinds to this machine; a
  // request that is not well formed (before its body is read).
  bool refused(const httplib::Request& request, httplib::Response& response) const {
    // Servers and proxies may read a different one of two Host headers.
    if (request.get_header_value_count("Host") > 1) {
      reply(response, 400, "a request may have one Host header only");
      return true;
    }
    // Without a length the body would be read until the client closes the
    // connection, or the read times out.
    if (request.method == "POST" && !request.has_header("Content-Length") &&
        !request.has_header("Transfer-Encoding")) {
      reply(response, 411, "a POST needs a Content-Length header (with curl: -d '')");
      return true;
    }
    const std::string host = request.get_header_value("Host");
    const std::string port = ":" + std::to_string(port_);
    if (isLoopback(address_) && host != ownHost() && host != "127.0.0.1" + port &&
        host != "localhost" + port && host != "[::1]" + port) {
      reply(response, 403, "this server answers only to its own address, not to Host " + host);
      return true;
    }
    if (request.has_header("Origin") && request.get_header_value("Origin") != "http://" + host) {
      reply(response, 403, "requests from other web pages are refused");
      return true;
    }
    return false;
  }

  void pass(const char* method, const httplib::Request& request, httplib::Response& response) {
    ViewReply answer = service_.handle(method, request.path, request.params);
    response.status = answer.status;
    for (const auto& [name, value] : answer.headers) response.set_header(name, value);
    response.set_content(std::move(answer.body), answer.type.c_str());
  }

  ViewService& service_;
  std::string address_;
  int port_ = 0;
  httplib::Server server_;
  std::thread thread_;
};

}  // namespace

std::unique_ptr<HttpServer> makeViewServer(ViewService& service, const std::string& address,
                                           int port) {
  return std::make_unique<ViewServer>(service, address, port);
}

}  // namespace csgray::detail
