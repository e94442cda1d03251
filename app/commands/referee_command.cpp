#include "commands/referee_command.h"

#include <fmt/format.h>
#include <stdlib.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <fstream>
#include <optional>

#include "cli/exit_status.h"
#include "cli/number_options.h"
#include "cli/output_paths.h"
#include "cli/seed_option.h"
#include "cli/subcommand.h"
#include "cli/verdict_command.h"
#include "core/error.h"
#include "render/interrupt.h"
#include "validation/compare/z_score_image.h"
#include "validation/referee/baseline.h"
#include "validation/referee/command_template.h"
#include "validation/referee/junit_report.h"
#include "validation/referee/manifest.h"
#include "validation/referee/process_render_source.h"
#include "validation/referee/referee.h"
#include "validation/referee/referee_report.h"

namespace verity {

namespace {

using namespace validation;

constexpr int kStatusEquivalent = 0, kStatusDiffer = 1, kStatusInconclusive = 3;

struct RefereeArgs {
  std::string a, b, baseline, saveBaseline, scene, rendererVersion, manifest;
  std::string json, junit, zImage, workDir, layer, spending = "pocock";
  double margin = 0.01, alpha = 0.01, maxSeconds = 0, renderTimeout = 0;
  int tile = 16, initialRenders = 4, maxRenders = 64, jobs = 2, spp = 0;
  uint64_t seed = 0;
};

// One comparison, checked and ready to render.
struct RefereeEntry {
  ManifestEntry given;
  RefereeOptions options;
  std::optional<int> spp;
  std::optional<double> renderTimeout;  // seconds per render; none: no limit
  std::optional<Baseline> baseline;
  std::string scene;  // --scene, or else the command template of the side it names
  std::filesystem::path zImage;
};

struct RefereeOutcome {
  int status = kBadInputStatus;
  double seconds = 0;
  std::string summary;  // the report, or the error
  nlohmann::json json;
};

int statusOf(Verdict v) {
  return v == Verdict::Equivalent ? kStatusEquivalent
         : v == Verdict::Differ   ? kStatusDiffer
                                  : kStatusInconclusive;
}

std::string lowercaseExtension(const std::string& file) {
  std::string e = std::filesystem::path(file).extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
  return e;
}

// --z-image Z.png for a manifest: Z-<entry name>.png beside it, the name's characters other than
// letters, digits, '-', '_' and '.' replaced by '_'.
std::filesystem::path entryZImage(const std::filesystem::path& zImage, const std::string& name) {
  std::string safe = name;
  for (char& c : safe)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '_';
  return zImage.parent_path() / (zImage.stem().string() + "-" + safe + zImage.extension().string());
}

// Every check that needs no render: the entry's options, templates, baseline and outputs.
RefereeEntry prepareEntry(const ManifestEntry& given, const RefereeArgs& args, bool inManifest) {
  RefereeEntry e;
  e.given = given;
  RefereeOptions& o = e.options;
  o.tileSize = args.tile;
  o.alpha = args.alpha;
  o.margin = given.margin.value_or(args.margin);
  o.initialRenders = given.initialRenders.value_or(args.initialRenders);
  o.maxRenders = given.maxRenders.value_or(args.maxRenders);
  o.maxSeconds = given.maxSeconds.value_or(args.maxSeconds);
  o.layer = args.layer;
  o.seed = args.seed;
  try {
    o.spending = spendingFunction(args.spending);
  } catch (const std::invalid_argument& error) {
    throw VerityError("", "--spending", error.what());
  }
  checkRefereeOptions(o);
  const double timeout = given.renderTimeout.value_or(args.renderTimeout);
  if (!(timeout >= 0) || !std::isfinite(timeout))
    throw VerityError(
        "", inManifest && given.renderTimeout ? "budget/render_timeout" : "--render-timeout",
        fmt::format("must be a time of at least 0 seconds (0: no limit), not {}", timeout));
  if (timeout > 0) e.renderTimeout = timeout;
  if (given.spp)
    e.spp = given.spp;
  else if (args.spp > 0)
    e.spp = args.spp;
  const char* aName = inManifest ? "a" : "--a";
  const char* bName = inManifest ? "b" : "--b";
  const char* baselineName = inManifest ? "baseline" : "--baseline";
  const char* saveName = inManifest ? "save_baseline" : "--save-baseline";
  if (!given.a.empty() && !given.baseline.empty())
    throw VerityError(
        "", baselineName,
        fmt::format("side A is either a command ({}) or a baseline, not both", aName));
  if (given.a.empty() && given.baseline.empty())
    throw VerityError("", aName, fmt::format("side A needs a render command or {}", baselineName));
  if (given.b.empty() && (given.a.empty() || given.saveBaseline.empty()))
    throw VerityError("", bName,
                      fmt::format("side B needs a render command (only {} with {} renders one "
                                  "side alone)",
                                  saveName, aName));
  if (!given.baseline.empty() && !given.saveBaseline.empty())
    throw VerityError(
        "", saveName,
        fmt::format("saves side A's renders, and with {} there are none", baselineName));
  if (!given.a.empty()) checkCommandTemplate(given.a, aName, e.spp);
  if (!given.b.empty()) checkCommandTemplate(given.b, bName, e.spp);
  // A manifest's --spp serves the entries that have {spp}; one given to this entry must be used.
  const bool sppForThisEntry = given.spp || (!inManifest && e.spp);
  if (sppForThisEntry && !hasPlaceholder(given.a, "spp") && !hasPlaceholder(given.b, "spp"))
    throw VerityError("", inManifest ? "spp" : "--spp",
                      "no render command has the placeholder {spp} to receive it");
  e.scene = !given.scene.empty() ? given.scene : !given.a.empty() ? given.a : given.b;
  if (!given.baseline.empty()) {
    e.baseline = loadBaseline(given.baseline);
    requireSameSetup(*e.baseline, given.baseline, e.scene, o.tileSize);
    requireNewSeeds(*e.baseline, given.baseline, o.seed, o.maxRenders);
  }
  if (!given.saveBaseline.empty()) prepareOutputFile(given.saveBaseline, saveName);
  if (!args.zImage.empty()) {
    e.zImage =
        inManifest ? entryZImage(args.zImage, given.name) : std::filesystem::path(args.zImage);
    prepareOutputFile(e.zImage, "--z-image");
  }
  return e;
}

void saveSide(const RefereeEntry& e, const TileMoments& moments, const RefereeArgs& args) {
  saveBaseline(e.given.saveBaseline,
               {e.scene, e.given.a, args.rendererVersion, e.options.seed, moments});
  fmt::print("wrote the baseline {} ({} renders)\n", e.given.saveBaseline.string(),
             moments.renders());
}

RefereeOutcome runEntry(const RefereeEntry& e, const RefereeArgs& args,
                        const std::filesystem::path& workDir) {
  RefereeOutcome out;
  out.json = {{"name", e.given.name},
              {"scene", e.scene},
              {"a", e.given.a},
              {"b", e.given.b},
              {"baseline", e.given.baseline.string()},
              {"renderer_version", args.rendererVersion}};
  const auto start = std::chrono::steady_clock::now();
  try {
    ProcessRenderSource source({e.given.a, e.given.b}, args.jobs, workDir, e.spp, e.renderTimeout);
    if (e.given.b.empty()) {
      const TileMoments moments = renderBaselineSide(source, e.options);
      saveSide(e, moments, args);
      out.status = 0;
      out.summary = fmt::format("baseline of {} renders saved\n", moments.renders());
      out.json["verdict"] = "BASELINE SAVED";
      out.json["renders_a"] = moments.renders();
    } else {
      const RefereeResult r =
          referee(source, e.options, e.baseline ? &e.baseline->moments : nullptr);
      out.status = statusOf(r.verdict);
      out.summary = refereeSummary(r, e.options);
      out.json.update(refereeJson(r, e.options));
      if (!e.zImage.empty()) {
        // A's mean image, the side "B above A" speaks of; a baseline keeps no pixels, so
        // then B's.
        ImageChannels image = r.a.meanImage();
        const bool fromA = !image.planes.empty();
        if (!fromA) image = r.b.meanImage();
        writeZScoreImage(e.zImage, r.comparison, image,
                         fmt::format("{}: mean of {} renders", fromA ? "A" : "B",
                                     (fromA ? r.a : r.b).renders()));
        out.summary += fmt::format("wrote {}\n", e.zImage.string());
      }
      if (!e.given.saveBaseline.empty()) saveSide(e, r.a, args);
    }
  } catch (const RendersInterrupted&) {
    throw;  // ends the whole run (run()'s work folder is removed on the way out)
  } catch (const std::exception& error) {
    out.status = kBadInputStatus;
    out.summary = fmt::format("verity: error: {}\n", error.what());
    out.json["verdict"] = "ERROR";
    out.json["error"] = error.what();
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out.json["exit_status"] = out.status;
  out.json["seconds_total"] = out.seconds;
  return out;
}

JunitCase junitCase(const std::string& name, const RefereeOutcome& o) {
  JunitCase c;
  c.name = name;
  c.seconds = o.seconds;
  c.details = o.summary;
  if (o.status == kStatusDiffer) {
    c.outcome = JunitCase::Outcome::Failure;
    c.type = "DIFFER";
    c.message = "the renders differ significantly";
  } else if (o.status == kStatusInconclusive) {
    c.outcome = JunitCase::Outcome::Error;
    c.type = "INCONCLUSIVE";
    c.message = "neither DIFFER nor EQUIVALENT within the budget: " +
                o.json.value("stop_reason", std::string());
  } else if (o.status == kBadInputStatus) {
    c.outcome = JunitCase::Outcome::Error;
    c.type = "bad input";
    const std::string error = o.json.value("error", std::string());
    c.message = error.substr(0, error.find('\n'));  // the details hold the rest
  }
  return c;
}

// A fresh folder for the renders, removed at the end, unless --work-dir names one.
struct WorkFolder {
  explicit WorkFolder(const std::string& given) {
    if (!given.empty()) {
      prepareOutputFolder(given, "--work-dir");
      path = given;
      return;
    }
    std::string pattern =
        (std::filesystem::temp_directory_path() / "verity-referee-XXXXXX").string();
    if (!mkdtemp(pattern.data()))
      throw VerityError("", "--work-dir",
                        "cannot create a folder for the renders in the temp folder");
    path = pattern;
    owned = true;
  }
  ~WorkFolder() {
    std::error_code ignored;
    if (owned) std::filesystem::remove_all(path, ignored);
  }
  std::filesystem::path path;
  bool owned = false;
};

int run(const RefereeArgs& args) {
  const bool manifest = !args.manifest.empty();
  std::vector<ManifestEntry> given;
  if (manifest) {
    for (const auto& [value, option] : {std::pair{args.a, "--a"},
                                        {args.b, "--b"},
                                        {args.baseline, "--baseline"},
                                        {args.saveBaseline, "--save-baseline"},
                                        {args.scene, "--scene"}})
      if (!value.empty())
        throw VerityError("", option, "is given per entry in a manifest (--manifest), not here");
    given = loadManifest(args.manifest);
  } else {
    ManifestEntry e;
    e.name = args.scene.empty() ? "referee" : args.scene;
    e.scene = args.scene;
    e.a = args.a;
    e.b = args.b;
    e.baseline = args.baseline;
    e.saveBaseline = args.saveBaseline;
    given.push_back(e);
  }
  // Everything is checked before the first render.
  if (!args.zImage.empty() && lowercaseExtension(args.zImage) != ".png")
    throw VerityError("", "--z-image",
                      "writes a PNG, so its name must end in .png, not \"" + args.zImage + "\"");
  if (!args.json.empty()) prepareOutputFile(args.json, "--json");
  if (!args.junit.empty()) prepareOutputFile(args.junit, "--junit");
  std::vector<RefereeEntry> entries;
  for (const ManifestEntry& m : given) {
    try {
      entries.push_back(prepareEntry(m, args, manifest));
    } catch (const VerityError& error) {
      if (!manifest) throw;
      throw VerityError(args.manifest, fmt::format("entry \"{}\"", m.name), error.what());
    }
  }
  const WorkFolder work(args.workDir);

  int status = kStatusEquivalent;
  nlohmann::json report = {{"entries", nlohmann::json::array()}};
  std::vector<JunitCase> cases;
  for (const RefereeEntry& e : entries) {
    if (manifest) fmt::print("== {}\n", e.given.name);
    const RefereeOutcome o = runEntry(e, args, work.path);
    // Errors go to stderr like every command's; verdicts to stdout.
    std::fflush(stdout);
    fmt::print(o.status == kBadInputStatus ? stderr : stdout, "{}", o.summary);
    std::fflush(o.status == kBadInputStatus ? stderr : stdout);
    // The worst outcome: bad input, then DIFFER, then INCONCLUSIVE.
    const auto rank = [](int s) {
      return s == kBadInputStatus ? 3 : s == kStatusDiffer ? 2 : s == kStatusInconclusive ? 1 : 0;
    };
    if (rank(o.status) > rank(status)) status = o.status;
    report["entries"].push_back(o.json);
    cases.push_back(junitCase(e.given.name, o));
  }
  report["exit_status"] = status;
  if (!args.json.empty()) {
    std::ofstream out(args.json);
    out << report.dump(2) << "\n";
    if (!out) throw VerityError(args.json, "", "cannot write the JSON report");
    fmt::print("wrote {}\n", args.json);
  }
  if (!args.junit.empty()) {
    writeJunit(args.junit, "verity referee", cases);
    fmt::print("wrote {}\n", args.junit);
  }
  return status;
}

}  // namespace

void addRefereeCommand(CLI::App& app, const ProcessGroup& group) {
  auto args = std::make_shared<RefereeArgs>();
  CLI::App* cmd = addSubcommand(
      app, "referee",
      "Render two sides in rounds until they DIFFER or are EQUIVALENT within --margin: "
      "--a \"CMD\" --b \"CMD\", --baseline FILE --b \"CMD\", or --manifest FILE. A command "
      "has {seed} and {out} (and {spp}). Exit status 0 EQUIVALENT, 1 DIFFER, 3 INCONCLUSIVE, "
      "2 bad input",
      MpiUse::OneProcess, group);
  cmd->add_option("--a", args->a, "Side A's render command: {seed}, {out} (an EXR), {spp}")
      ->type_name("CMD");
  cmd->add_option("--b", args->b, "Side B's render command, like --a")->type_name("CMD");
  cmd->add_option("--baseline", args->baseline,
                  "Side A is this baseline (saved by --save-baseline); only B is rendered")
      ->type_name("FILE");
  cmd->add_option("--save-baseline", args->saveBaseline,
                  "Save side A's tile statistics as a baseline (with --a and no --b: render "
                  "--max-renders of A and save them)")
      ->type_name("FILE");
  cmd->add_option("--scene", args->scene,
                  "The scene's name, stored in a baseline and checked against it (default: "
                  "the command template)");
  cmd->add_option("--renderer-version", args->rendererVersion,
                  "The renderer's version, stored in a saved baseline and the JSON report");
  cmd->add_option("--manifest", args->manifest,
                  "A JSON suite of comparisons (docs/referee.md); --junit writes one test case "
                  "per entry")
      ->type_name("FILE");
  cmd->add_option("--margin", args->margin,
                  "EQUIVALENT when every tile's expectation lies within this relative margin "
                  "of A's, e.g. 0.01")
      ->check(realNumber(0, false, 1, false));
  cmd->add_option("--alpha", args->alpha,
                  "The level of a false DIFFER, and of a false EQUIVALENT, over all rounds")
      ->check(realNumber(0, false, 0.5, false));
  cmd->add_option("--tile", args->tile, "Tile size in pixels")->check(wholeNumber(1));
  cmd->add_option("--initial-renders", args->initialRenders,
                  "Renders per side in the first round; each round doubles them")
      ->check(wholeNumber(2));
  cmd->add_option("--max-renders", args->maxRenders, "Renders per side at most")
      ->check(wholeNumber(2));
  cmd->add_option("--max-seconds", args->maxSeconds,
                  "The time budget: no round starts after it, and the renders still running "
                  "at its end are stopped (INCONCLUSIVE; 0: no limit)")
      ->check(realNumber(0, true));
  cmd->add_option("--render-timeout", args->renderTimeout,
                  "Seconds one render may take: one that runs longer is killed, with its "
                  "process group, and is an error naming its command (exit 2; 0: no limit)")
      ->check(realNumber(0, true));
  cmd->add_option("--spending", args->spending,
                  "How the level is spent over the rounds: pocock or obrien-fleming (Lan and "
                  "DeMets 1983)");
  cmd->add_option("--jobs,-j", args->jobs, "Renders run at once")->check(wholeNumber(1, 1024));
  cmd->add_option("--spp", args->spp, "The value of {spp} in the commands")
      ->default_str("none")
      ->check(wholeNumber(1));
  addSeedOption(cmd, args->seed, "Render i of A has seed SEED + 2i, of B SEED + 2i + 1")
      ->default_str("0");
  cmd->add_option("--layer", args->layer, "Read R, G, B from this EXR layer")->type_name("NAME");
  cmd->add_option("--json", args->json, "Write everything (rounds, tiles) to this JSON file")
      ->type_name("FILE");
  cmd->add_option("--junit", args->junit, "Write a JUnit XML report: one test case per entry")
      ->type_name("FILE");
  cmd->add_option("--z-image", args->zImage,
                  "Write each entry's z-scores as a PNG (a manifest's entries: FILE-NAME.png)")
      ->type_name("FILE.png");
  cmd->add_option("--work-dir", args->workDir,
                  "Render here (default: a fresh temporary folder, removed at the end)")
      ->type_name("DIR");
  cmd->callback([args] {
    throw CLI::RuntimeError(runVerdictCommand([&] {
      const InterruptGuard guard(/*alsoTerminate=*/true);
      try {
        return run(*args);
      } catch (const RendersInterrupted& e) {
        fmt::print(stderr, "verity: {}: no decision\n", e.what());
        return kInterruptedStatus;
      }
    }));
  });
}

}  // namespace verity
