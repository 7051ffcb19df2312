// The answers to the page's requests (view_server.h lists them), from a
// ViewSession: the parsing of their parameters, the JSON, the statuses.
#pragma once

#include "view/view_jobs.h"
#include "view/view_service.h"
#include "view/view_session.h"

namespace csgray::detail {

class ViewRoutes final : public ViewService {
 public:
  // jobs: those of the export and check buttons; none: they are refused.
  explicit ViewRoutes(ViewSession& session, ViewJobs* jobs = nullptr)
      : session_(session), jobs_(jobs) {}
  ViewReply handle(const std::string& method, const std::string& path,
                   const std::multimap<std::string, std::string>& query) override;
  void shutdown() override { session_.shutdown(); }

 private:
  ViewReply job(const std::string& method, const std::string& path,
                const std::multimap<std::string, std::string>& query);

  ViewSession& session_;
  ViewJobs* jobs_;
};

}  // namespace csgray::detail
