#include <verity/chi2/subject.h>

namespace verity::chi2 {

void Subject::sampleBatch(pcg32& rng, std::vector<std::optional<Point2d>>& out,
                          Audit& audit) const {
  for (std::optional<Point2d>& p : out) p = sample(rng, audit);
}

void Subject::pdfBatch(const std::vector<Point2d>& points, std::vector<double>& values) const {
  for (size_t k = 0; k < points.size(); ++k) values[k] = pdf(points[k].x(), points[k].y());
}

}  // namespace verity::chi2
