// The answers to the page's requests (view_server.h lists them), from a
// ViewSession: the parsing of their parameters, the JSON, the statuses.
#pragma once

#include "view/view_service.h"
#include "view/view_session.h"

namespace csgray::detail {

class ViewRoutes final : public ViewService {
 public:
  explicit ViewRoutes(ViewSession& session) : session_(session) {}
  ViewReply handle(const std::string& method, const std::string& path,
                   const std::multimap<std::string, std::string>& query) override;
  void shutdown() override { session_.shutdown(); }

 private:
  ViewSession& session_;
};

}  // namespace csgray::detail
