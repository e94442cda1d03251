#include "chi2/suite/figure.h"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <vector>

#include "core/error.h"
#include "core/program_files.h"

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

std::vector<double> edges(double lo, double hi, int cells) {
  std::vector<double> e(cells + 1);
  for (int i = 0; i <= cells; ++i) e[i] = lo + (hi - lo) * i / cells;
  e[cells] = hi;
  return e;
}

// Cell values as rows of constant y (numpy's (ny, nx) layout).
template <class T>
nlohmann::json rows(const std::vector<T>& cells, const Domain& d) {
  nlohmann::json out = nlohmann::json::array();
  for (int j = 0; j < d.ny; ++j)
    out.push_back(std::vector<T>(cells.begin() + j * d.nx, cells.begin() + (j + 1) * d.nx));
  return out;
}

}  // namespace

nlohmann::json figureData(const TestResult& r) {
  const Domain& d = r.domain;
  const Axes axes = axesOf(d.kind);
  const ChiSquareResult& c = r.chiSquare;
  nlohmann::json j;
  j["subject"] = r.subject;
  j["verdict"] = verdictName(r.verdict());
  j["inconclusive_reason"] = r.inconclusiveReason();
  j["samples"] = r.samples;
  j["valid"] = r.valid;
  j["outside"] = r.outside;
  j["significance"] = r.significance;
  j["domain"] = {{"kind", axes.kind},
                 {"name", d.name()},
                 {"nx", d.nx},
                 {"ny", d.ny},
                 {"x_label", axes.x},
                 {"y_label", axes.y},
                 {"x_edges", edges(d.x0, d.x1, d.nx)},
                 {"y_edges", edges(d.y0, d.y1, d.ny)}};
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
  return j;
}

std::string writeFigure(const TestResult& result, const std::string& prefix) {
  const std::string data = prefix + ".json", png = prefix + ".png";
  {
    std::ofstream out(data);
    if (!(out << figureData(result).dump() << '\n'))
      throw VerityError(data, "", "cannot write the chi-square histogram");
  }
  // The figure is a convenience, but a missing one is an error rather than a silent gap.
  std::filesystem::path python;
  try {
    python = findPythonWith("matplotlib", "draw the chi-square figure");
  } catch (const VerityError& e) {
    throw VerityError(data, "", e.problem() + "; the histogram is in this file");
  }
  const std::filesystem::path script = sharedProgramFile("plot_chi2.py");
  const int status = runProgram({python.string(), script.string(), data, png});
  if (status != 0)
    throw VerityError(data, "",
                      fmt::format("cannot draw the chi-square figure: {} {} failed (exit status "
                                  "{}); the histogram is in this file",
                                  python.string(), script.string(), status));
  return png;
}

}  // namespace verity::chi2
