#include "check/point_classification.h"

#include <tbb/parallel_for.h>

#include <cstdint>
#include <random>
#include <vector>

#include "engine/cancellation.h"

namespace csgray::detail {

namespace {

constexpr std::size_t kListed = 10;  // disagreeing points listed

}  // namespace

void classifyPoints(const Solid& solid, const MeshProbe& probe, const ExactDistance& distances,
                    const Bounds& box, const CheckOptions& options, CheckReport& report) {
  std::mt19937_64 rng(options.seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<dvec3> points(options.samples);
  for (dvec3& p : points) p = box.lo + dvec3(uniform(rng), uniform(rng), uniform(rng)) * box.size();
  enum Verdict : std::uint8_t { Agree, InBand, Disagree };
  std::vector<std::uint8_t> verdicts(points.size());

  if (!points.empty()) probe.side(points[0]);  // builds CGAL's tree before the threads ask
  tbb::parallel_for(std::size_t(0), points.size(), [&, cancel = cancelFlag()](std::size_t k) {
    stopIfCancelled(cancel);
    const MeshProbe::Side side = probe.side(points[k]);
    const bool exact = solid.contains(points[k]);
    if (side == MeshProbe::Side::Boundary)
      verdicts[k] = InBand;
    else if (exact == (side == MeshProbe::Side::Inside))
      verdicts[k] = Agree;
    else
      verdicts[k] = distances.withinBand(points[k]) ? InBand : Disagree;
  });
  report.points = points.size();
  for (std::size_t k = 0; k < points.size(); ++k) {
    if (verdicts[k] == Agree) ++report.agree;
    if (verdicts[k] == InBand) ++report.inBand;
    if (verdicts[k] != Disagree) continue;
    ++report.disagreementCount;
    if (report.disagreements.size() < kListed) report.disagreements.push_back(points[k]);
  }
}

}  // namespace csgray::detail
