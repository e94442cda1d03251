#include <verity/chi2/figure_data.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <vector>

namespace verity::chi2 {

namespace {

struct Axes {
  const char* kind;
  const char* x;
  const char* y;
};

Axes axesOf(DomainKind kind) {
  switch (kind) {
    case DomainKind::Sphere:
      return {"sphere", "φ (radians)", "cos θ"};
    case DomainKind::Disk:
      return {"disk", "x", "y"};
    case DomainKind::Triangle:
      return {"triangle", "b₀ (barycentric)", "b₁ (barycentric)"};
    default:
      return {"square", "x", "y"};
  }
}

// Cell values as rows of constant j (numpy's (ny, nx) layout).
template <class T>
nlohmann::json rows(const std::vector<T>& cells, const Domain& d) {
  nlohmann::json out = nlohmann::json::array();
  for (int j = 0; j < d.ny; ++j)
    out.push_back(std::vector<T>(cells.begin() + j * d.nx, cells.begin() + (j + 1) * d.nx));
  return out;
}

}  // namespace

std::string figureJson(const TestResult& r) {
  const Domain& d = r.domain;
  const Axes axes = axesOf(d.kind);
  const ChiSquareResult& c = r.chiSquare;
  std::vector<double> xEdges;
  for (int i = 0; i <= d.nx; ++i) xEdges.push_back(d.xEdge(i));
  // Strip i's own edges in y: one list per strip, the same lists on the uniform grid.
  nlohmann::json yEdges = nlohmann::json::array();
  for (int i = 0; i < d.nx; ++i) {
    std::vector<double> strip;
    for (int j = 0; j <= d.ny; ++j) strip.push_back(d.yEdge(i, j));
    yEdges.push_back(strip);
  }
  nlohmann::json j;
  j["subject"] = r.subject;
  j["verdict"] = verdictName(r.verdict());
  j["inconclusive_reason"] = r.inconclusiveReason();
  j["samples"] = r.samples;
  j["valid"] = r.valid;
  j["outside"] = r.outside;
  j["audit"] = {
      {"compared_samples", r.auditedSamples}, {"reach", r.auditReach}, {"power", r.auditPower}};
  j["significance"] = r.significance;
  j["domain"] = {{"kind", axes.kind},
                 {"name", d.name()},
                 {"nx", d.nx},
                 {"ny", d.ny},
                 {"x_label", axes.x},
                 {"y_label", axes.y},
                 {"uniform", d.uniform()},
                 {"x_edges", xEdges},
                 {"y_edges", yEdges}};
  j["observed"] = rows(r.observed, d);
  j["expected"] = rows(r.expected, d);
  j["chi_square"] = {{"passed", r.chiSquarePassed()},   {"p_value", c.pValue},
                     {"statistic", c.statistic},        {"dof", c.dof},
                     {"degenerate", c.degenerate},      {"regular_cells", c.regularCells},
                     {"pooled_cells", c.pooledCells},   {"outright_samples", c.outrightSamples},
                     {"outright_cell", c.outrightCell}, {"description", c.describe()}};
  j["integral"] = {{"passed", r.integral.passed},
                   {"integral", r.integral.integral},
                   {"lower", r.integral.lower},
                   {"upper", r.integral.upper},
                   {"tolerance", r.integral.tolerance},
                   {"description", r.integral.describe()},
                   {"quadrature_error", r.quadratureError}};
  j["audit"] = {{"passed", r.audit.clean()}, {"description", r.audit.describe()}};
  // Seconds per phase (phase_times.h) as far as the check had gone when this was written.
  nlohmann::json phases;
  for (int p = 0; p < static_cast<int>(Phase::Count); ++p)
    phases[phaseName(static_cast<Phase>(p))] = r.phases[static_cast<Phase>(p)];
  j["seconds"] = r.seconds;
  j["phases"] = phases;
  return j.dump();
}

void writeFigureData(const TestResult& result, const std::string& path) {
  std::ofstream out(path);
  if (!(out << figureJson(result) << '\n'))
    throw std::runtime_error(path + ": cannot write the chi-square histogram");
}

}  // namespace verity::chi2
