#include <verity/stats/pixel_statistics.h>

#include <sstream>

namespace verity::validation {

PixelStatistics scaledStatistics(PixelStatistics s, double factor) {
  std::ostringstream label;
  label << s.label << " x" << factor;
  s.label = label.str();
  for (int c = 0; c < kChannels; ++c) {
    for (double& m : s.mean[c]) m *= factor;
    for (double& v : s.variance[c]) v *= factor * factor;
  }
  return s;
}

}  // namespace verity::validation
