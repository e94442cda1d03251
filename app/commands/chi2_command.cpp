#include "commands/chi2_command.h"

#include <fmt/format.h>
#include <unistd.h>
#include <verity/chi2/check_result.h>
#include <verity/chi2/delta_check.h>
#include <verity/chi2/significance.h>

#include <iostream>
#include <optional>
#include <sstream>

#include "chi2/suite/figure.h"
#include "chi2/suite/suite.h"
#include "cli/exit_status.h"
#include "cli/number_options.h"
#include "cli/output_paths.h"
#include "cli/seed_option.h"
#include "cli/subcommand.h"
#include "cli/threads_option.h"
#include "cli/verdict_command.h"
#include "commands/check_progress_display.h"
#include "commands/chi2_sweep.h"
#include "core/error.h"
#include "core/thread_arena.h"

namespace verity {

namespace {

// The exit statuses of `verity chi2`, one per verdict, and one for input it cannot use.
constexpr int kPassed = 0, kFailed = 1, kInconclusive = 3;

int exitStatus(chi2::Verdict verdict) {
  switch (verdict) {
    case chi2::Verdict::Passed:
      return kPassed;
    case chi2::Verdict::Failed:
      return kFailed;
    case chi2::Verdict::Inconclusive:
      return kInconclusive;
  }
  return kFailed;
}

struct Chi2Args {
  std::string material;
  double incoming = 0;
  std::string normal = "0,0,1";
  bool inside = false;
  long long samples = chi2::suite::kSamples;
  double alpha = 0.01;
  double power = chi2::kDefaultPower;
  std::optional<double> detect;
  double mass = chi2::kStatedMass;
  long long maxSamples = 100'000'000;
  std::optional<long long> auditedSamples;
  uint64_t seed = 1;
  std::string output;
  bool seedTable = false;
  std::string cells = "equal";  // chi2::parseCellLayout
  bool timings = false;
  int threads = 0;
  // --sweep: the material as a family (chi2_sweep.h).
  std::vector<std::string> sweeps;
  std::vector<double> incidences{0, 30, 60, 85, 89.9, 90};
  bool fromBelow = false;
  int interiorPoints = 8;
};

// The index a delta refraction is held to: none within 10⁻³ of index matching, which the
// renderer treats as a pass-through (rough_dielectric.h).
std::optional<double> deltaRefractionIndex(double eta) {
  return std::abs(eta - 1) > 1e-3 ? std::optional<double>(eta) : std::nullopt;
}

Vector3f parseVector(const std::string& text) {
  std::stringstream ss(text);
  Vector3f v;
  char comma;
  if (!(ss >> v.x() >> comma >> v.y() >> comma >> v.z()) || v.norm() == 0)
    throw CLI::ValidationError("--normal", "expected x,y,z with a non-zero length");
  return v.normalized();
}

// The run's options as the library's: --alpha is the probability that a correct material
// fails this run, shared by its statistical tests with Šidák's correction.
chi2::TestOptions testOptions(const Chi2Args& a) {
  chi2::TestOptions o;
  o.samples = a.samples;
  o.seed = a.seed;
  o.significance = chi2::sidakLevel(a.alpha, chi2::kStatisticalTestsPerCheck);
  o.power = a.power;
  if (!(a.power > o.significance))
    throw std::invalid_argument(fmt::format(
        "--power: must exceed the per-test level {:.3g}, or no test could reach it, not {}",
        o.significance, a.power));
  if (a.detect) o.detect = chi2::DetectionTarget{*a.detect, a.mass, a.power};
  o.maxSamples = a.maxSamples;
  o.auditedSamples = a.auditedSamples;
  o.cells = chi2::parseCellLayout(a.cells);
  return o;
}

void printResult(const chi2::TestResult& r, const Chi2Args& a) {
  std::cout << r.report() << "\n";
  std::cout << fmt::format(
      "  level {:.3g} per test: Sidak over this run's {} statistical tests for a family-wise "
      "level of {} (--alpha)\n",
      r.significance, chi2::kStatisticalTestsPerCheck, a.alpha);
}

// The material --material describes; its errors name the option and the JSON path in it.
std::shared_ptr<const Material> materialOption(const std::string& json) {
  try {
    return chi2::suite::makeMaterial(json);
  } catch (const VerityError& e) {
    throw VerityError("--material", e.jsonPath(), e.problem());
  }
}

int runOne(const Chi2Args& a) {
  chi2::BsdfSetup s;
  s.name = a.material;
  s.material = materialOption(a.material);
  s.normal = parseVector(a.normal);
  s.wi = chi2::incidentDirection(a.incoming, a.inside);
  s.resolution = chi2::suite::kSphereResolution;
  chi2::BsdfSubject subject(s);
  chi2::TestOptions options = testOptions(a);
  chi2::CheckProgress progress;
  options.progress = &progress;
  std::optional<CheckProgressDisplay> display(std::in_place, progress, isatty(STDERR_FILENO));
  chi2::TestResult r = chi2::runSamplingTest(subject, options);
  std::optional<chi2::DeltaCheck> delta;
  if (r.deltaSamples > 0) {
    progress.phase = chi2::Phase::DeltaLobes;
    // The delta lobes on draws of their own: directions, weights, shares and albedos. The
    // renderer treats an interface within 1e-3 of index matching as a pass-through
    // (rough_dielectric.h), so only a larger contrast is held to Snell's law.
    const chi2::PhaseTimer timer(r.phases, chi2::Phase::DeltaLobes);
    chi2::DeltaCheckOptions d;
    d.eta = deltaRefractionIndex(subject.model().relativeIndex());
    delta = chi2::checkDeltaLobes(subject.model(), subject.localWi(), d, chi2::deltaDraws(r),
                                  r.significance, options.seed);
    r.deltaLobesChecked = true;
  }
  display.reset();
  printResult(r, a);
  chi2::Verdict verdict = r.verdict();
  if (delta) {
    if (!delta->passed()) verdict = chi2::Verdict::Failed;
    std::cout << delta->report() << "\n  " << chi2::verdictName(verdict)
              << " with the delta lobes\n";
  }
  // Only the histogram's statistical tests failed (every sample agreed, and the delta lobes
  // passed), which a correct material does at the level's rate: say so, since that is not yet
  // a defect.
  if (r.verdict() == chi2::Verdict::Failed && r.outside == 0 && r.audit.clean() &&
      (!delta || delta->passed()))
    std::cout << fmt::format(
        "  only the statistical tests failed, which a correct material does with probability "
        "{} (--alpha): rerun with another --seed, and more --samples, to tell chance from a "
        "defect\n",
        a.alpha);
  if (!a.output.empty()) {
    prepareOutputFile(a.output + ".json", "-o");
    const chi2::PhaseClock clock;
    const std::string figure = chi2::writeFigure(r, a.output);
    r.phases.add(chi2::Phase::Figure, clock.seconds());
    std::cout << "  wrote " << figure << " (histogram in " << a.output << ".json)\n";
  }
  if (a.timings) {
    long long binned = 0;
    const double floor = subject.drawingFloorSeconds(r.domain, r.samples, options.seed, binned);
    std::cout << fmt::format(
        "  time by phase: {}; total {:.3f} s\n  floor: drawing the same {} samples on one "
        "thread and binning them, without audit, density or statistics: {:.3f} s; the check "
        "took {:.2f} times that\n",
        r.phases.describe(), r.phases.total(), r.samples, floor, r.phases.total() / floor);
  }
  return exitStatus(verdict);
}

// The seed report's sample test (shared/seed/final-project-report.txt §3.3): alpha 0.3,
// ior 0.34, extinction 3.9, normals sampled by D(m) cos θm; the rotated variants use the
// shading normal normalize(0.25, 0.5, 1) with the incident direction unchanged. Its
// incident direction, normalize(0.25, 0, −1) as a direction of travel, is wi =
// normalize(−0.25, 0, 1) pointing away from the surface.
int seedTable(const Chi2Args& a) {
  struct Row {
    const char* name;
    const char* type;
    bool rotated;
    double seedIntegral;
    int seedValid;
  };
  const Row rows[] = {{"beckmann", "beckmann", false, 1.04291, 99},
                      {"ggx", "ggx", false, 0.978916, 91},
                      {"rotated-beckmann", "beckmann", true, 1.02772, 98},
                      {"rotated-ggx", "ggx", true, 0.950388, 88}};
  std::cout << fmt::format("{:<18} {:>9} {:>7} | {:<8} {:>9} {:>9} {:>9} {:>10}\n", "test",
                           "seed int", "seed %", "sampling", "integral", "% valid", "int check",
                           "chi2 p");
  std::vector<std::string> notPassed;  // the reports of the rows that did not pass
  for (const Row& row : rows)
    for (const char* sampling : {"normals", "visible"}) {
      chi2::BsdfSetup s;
      s.material = chi2::suite::makeMaterial(
          fmt::format(R"({{"type":"{}","alpha":0.3,"ior":0.34,"ext":3.9,"sampling":"{}"}})",
                      row.type, sampling));
      s.name = row.name;
      s.normal = row.rotated ? chi2::suite::rotatedNormal() : Vector3f::UnitZ();
      s.wi = Vector3f(-0.25f, 0.0f, 1.0f).normalized();
      s.resolution = chi2::suite::kSphereResolution;
      chi2::BsdfSubject subject(s);
      chi2::TestOptions o = testOptions(a);
      o.seed = chi2::seedFromName(std::string("seed_table_") + row.name + sampling);
      const chi2::TestResult r = chi2::runSamplingTest(subject, o);
      if (!r.passed()) notPassed.push_back(r.report());
      std::cout << fmt::format(
          "{:<18} {:>9.6f} {:>6}% | {:<8} {:>9.6f} {:>8.3f}% {:>9} {:>10.3g}\n", row.name,
          row.seedIntegral, row.seedValid, sampling, r.integral.integral,
          100.0 * r.valid / r.samples, r.integral.passed ? "pass" : "FAIL",
          r.chiSquare.degenerate ? 1.0 : r.chiSquare.pValue);
    }
  std::cout << "The seed's figures fail the integral check: with invalid samples weighted zero, "
               "the pdf must integrate to the valid fraction.\n";
  for (const std::string& report : notPassed) std::cout << "\n" << report << "\n";
  return notPassed.empty() ? 0 : 1;
}

// --sweep: --alpha is the family's level, --seed draws the interior points, and each check
// is sized by --detect, or draws --samples where given, else finds a 2% error over 1/4 of the
// mass.
int runSweep(const Chi2Args& a, bool samplesGiven) {
  std::vector<SweptKey> sweeps;
  for (const std::string& s : a.sweeps) sweeps.push_back(parseSweep(s));
  chi2::FamilyOptions o;
  o.incidences = a.incidences;
  o.fromBelow = a.fromBelow;
  o.interiorPoints = a.interiorPoints;
  o.seed = a.seed;
  o.level = a.alpha;
  o.check.power = a.power;
  o.check.cells = chi2::parseCellLayout(a.cells);
  o.check.maxSamples = a.maxSamples;
  o.check.auditedSamples = a.auditedSamples;
  if (a.detect) {
    o.check.detect = chi2::DetectionTarget{*a.detect, a.mass, a.power};
  } else if (samplesGiven) {
    o.check.detect.reset();
    o.check.samples = a.samples;
  } else {
    o.check.detect->power = a.power;
  }
  o.configure = [](const chi2::FamilyConfiguration&, const chi2::BsdfModel& model,
                   chi2::BsdfCheckOptions& check) {
    check.delta.eta = deltaRefractionIndex(model.relativeIndex());
  };
  return exitStatus(runChi2Sweep(a.material, sweeps, o, a.output));
}

}  // namespace

void addChi2Command(CLI::App& app, const ProcessGroup& group) {
  auto args = std::make_shared<Chi2Args>();
  CLI::App* cmd = addSubcommand(
      app, "chi2",
      "Chi-square test of one material's sampling (or the seed report's table); exit status 0 "
      "PASSED, 1 FAILED, 2 bad input, 3 INCONCLUSIVE (a check could not run with its stated "
      "power: the reason is printed)",
      MpiUse::OneProcess, group);
  cmd->add_option("--material", args->material, "the material as JSON, e.g. '{\"type\":\"ggx\"}'");
  cmd->add_option("--incoming", args->incoming, "incidence angle from +z in degrees, 0 to 90")
      ->check(realNumber(0, true, 90, true));
  cmd->add_option("--normal", args->normal, "shading normal x,y,z (world space)");
  cmd->add_flag("--inside", args->inside, "incident direction from below the surface");
  CLI::Option* samples =
      cmd->add_option(
             "--samples", args->samples,
             fmt::format("number of samples (the suite's sweep draws what a {:g}% "
                         "density error over 1/4 of the mass needs, --detect {:g})",
                         100 * chi2::suite::kSweepDensityError, chi2::suite::kSweepDensityError))
          ->check(wholeNumber(1, LLONG_MAX));
  cmd->add_option("--alpha", args->alpha,
                  "the probability that a correct material fails this run (its two statistical "
                  "tests share it by Sidak's correction)")
      ->check(realNumber(0, false, 1, false))
      ->capture_default_str();
  cmd->add_option("--power", args->power,
                  "the probability at which the verdict states what it could have caught, and "
                  "with which --detect must find its error")
      ->check(realNumber(0, false, 1, false))
      ->capture_default_str();
  CLI::Option* detect =
      cmd->add_option(
             "--detect", args->detect,
             "the relative density error to find (e.g. 0.01): over cells holding --mass of "
             "the distribution the density is 1 + EPS times the claimed one, and 1 - EPS "
             "over other cells holding --mass; the test draws the samples this needs, "
             "instead of --samples")
          ->type_name("EPS")
          ->check(realNumber(0, false, 1, true))
          ->excludes(samples);
  cmd->add_option("--mass", args->mass, "the mass each side of the --detect error covers")
      ->check(realNumber(0, false, 0.5, true))
      ->needs(detect)
      ->capture_default_str();
  cmd->add_option("--max-samples", args->maxSamples,
                  "the budget of --detect: a target that needs more samples is INCONCLUSIVE, "
                  "never PASSED")
      ->check(wholeNumber(1, LLONG_MAX))
      ->needs(detect)
      ->capture_default_str();
  cmd->add_option("--audited-samples", args->auditedSamples,
                  "compare each sample's weight, sample pdf and reciprocity on the first N "
                  "samples only (whole blocks of 65536), the report stating what that subsample "
                  "could have met; every sample when not given")
      ->type_name("N")
      ->check(wholeNumber(1, LLONG_MAX));
  addSeedOption(cmd, args->seed, "random seed, 0 to 2^64 - 1")->default_str("1");
  cmd->add_option("-o,--output", args->output,
                  "file name prefix: writes PREFIX.png, observed and expected counts and "
                  "(O-E)/sqrt(E) (drawn with matplotlib by python3 from PATH, else "
                  "/usr/bin/python3, or $VERITY_PYTHON), and its data "
                  "PREFIX.json; missing folders are created")
      ->type_name("PREFIX");
  cmd->add_option("--cells", args->cells,
                  "the histogram's cells: 'grid', the uniform grid of (phi, cos theta), or "
                  "'equal', of equal probability under the claimed pdf (a narrow lobe keeps as "
                  "many cells as a diffuse one; slower)")
      ->check(CLI::IsMember({"equal", "grid"}))
      ->default_str("equal");
  cmd->add_flag("--timings", args->timings,
                "print the seconds each phase took (cells, quadrature, drawing, audit, binning, "
                "delta lobes, statistics, figure) beside the floor: the time to draw and bin "
                "the same samples on one thread");
  CLI::Option* seedTableOption =
      cmd->add_flag("--seed-table", args->seedTable, "print the seed report's table next to ours");
  CLI::Option* sweep =
      cmd->add_option("--sweep", args->sweeps,
                      "check the material as a family: set KEY of --material to every corner of "
                      "the box of the swept ranges and to stratified points inside it, each at "
                      "every --incidences, at one family-wise level (--alpha); repeat for each "
                      "key; -o PREFIX writes PREFIX.md, PREFIX.json and PREFIX.xml (JUnit)")
          ->type_name("KEY=LO:HI[:log]")
          ->excludes(seedTableOption);
  for (const char* single : {"--incoming", "--normal", "--inside", "--timings"})
    sweep->excludes(cmd->get_option(single));
  cmd->add_option("--incidences", args->incidences,
                  "with --sweep: the incidence angles from +z in degrees, 0 to 90")
      ->delimiter(',')
      ->check(realNumber(0, true, 90, true))
      ->needs(sweep)
      ->default_str("0,30,60,85,89.9,90");
  cmd->add_flag("--from-below", args->fromBelow,
                "with --sweep: every incidence from below the surface too (a material that "
                "transmits)")
      ->needs(sweep);
  cmd->add_option("--interior-points", args->interiorPoints,
                  "with --sweep: points inside the box besides its corners (a Latin hypercube "
                  "drawn from --seed)")
      ->check(wholeNumber(0, 10000))
      ->needs(sweep)
      ->capture_default_str();
  addThreadsOption(cmd, args->threads, MpiUse::OneProcess);
  cmd->callback([args, samples] {
    if (!args->seedTable && args->material.empty())
      throw CLI::RequiredError("--material (or --seed-table)");
    const bool samplesGiven = samples->count() > 0;
    const int status = ThreadArena(args->threads).execute([&] {
      return runVerdictCommand([&] {
        if (args->seedTable) return seedTable(*args);
        return args->sweeps.empty() ? runOne(*args) : runSweep(*args, samplesGiven);
      });
    });
    if (status != kPassed) throw CLI::RuntimeError(status);
  });
}

}  // namespace verity
