#include "validation/referee/manifest.h"

#include <fmt/format.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "core/error.h"
#include "validation/referee/json_file.h"

namespace verity::validation {

namespace {

void onlyKeys(const nlohmann::json& node, const std::set<std::string>& keys,
              const std::string& file, const std::string& path) {
  for (const auto& [key, value] : node.items())
    if (!keys.count(key))
      throw VerityError(file, path + key,
                        fmt::format("unknown key; an entry knows name, scene, a, b, baseline, "
                                    "save_baseline, margin, spp and budget (initial_renders, "
                                    "max_renders, max_seconds, render_timeout)"));
}

}  // namespace

std::vector<ManifestEntry> loadManifest(const std::filesystem::path& file) {
  const std::string name = file.string();
  const nlohmann::json j = readJsonFile(file, "manifest");
  if (!j.is_object() || !j.contains("entries") || !j["entries"].is_array() || j["entries"].empty())
    throw VerityError(name, "/entries", "a manifest needs a non-empty array \"entries\"");
  const std::filesystem::path folder = file.parent_path();
  std::vector<ManifestEntry> entries;
  std::set<std::string> names;
  for (size_t i = 0; i < j["entries"].size(); ++i) {
    const nlohmann::json& e = j["entries"][i];
    const std::string path = fmt::format("/entries/{}/", i);
    std::string key;
    try {
      if (!e.is_object()) throw VerityError(name, path, "an entry must be an object");
      onlyKeys(e,
               {"name", "scene", "a", "b", "baseline", "save_baseline", "margin", "spp", "budget"},
               name, path);
      ManifestEntry entry;
      key = "name";
      if (!e.contains("name")) throw VerityError(name, path + "name", "missing");
      entry.name = e["name"].get<std::string>();
      if (entry.name.empty() || !names.insert(entry.name).second)
        throw VerityError(name, path + "name",
                          fmt::format("\"{}\": names must be non-empty and unique", entry.name));
      const auto text = [&](const char* k) {
        key = k;
        return e.contains(k) ? e[k].get<std::string>() : std::string();
      };
      entry.scene = text("scene");
      entry.a = text("a");
      entry.b = text("b");
      const auto relative = [&](const std::string& p) {
        return p.empty()                                ? std::filesystem::path()
               : std::filesystem::path(p).is_absolute() ? std::filesystem::path(p)
                                                        : folder / p;
      };
      entry.baseline = relative(text("baseline"));
      entry.saveBaseline = relative(text("save_baseline"));
      key = "margin";
      if (e.contains("margin")) entry.margin = e["margin"].get<double>();
      key = "spp";
      if (e.contains("spp")) entry.spp = e["spp"].get<int>();
      if (e.contains("budget")) {
        const nlohmann::json& budget = e["budget"];
        key = "budget";
        if (!budget.is_object()) throw VerityError(name, path + "budget", "must be an object");
        onlyKeys(budget, {"initial_renders", "max_renders", "max_seconds", "render_timeout"}, name,
                 path + "budget/");
        key = "budget/initial_renders";
        if (budget.contains("initial_renders"))
          entry.initialRenders = budget["initial_renders"].get<int>();
        key = "budget/max_renders";
        if (budget.contains("max_renders")) entry.maxRenders = budget["max_renders"].get<int>();
        key = "budget/max_seconds";
        if (budget.contains("max_seconds")) entry.maxSeconds = budget["max_seconds"].get<double>();
        key = "budget/render_timeout";
        if (budget.contains("render_timeout"))
          entry.renderTimeout = budget["render_timeout"].get<double>();
      }
      entries.push_back(std::move(entry));
    } catch (const nlohmann::json::exception& error) {
      throw VerityError(name, path + key, fmt::format("wrong type: {}", error.what()));
    }
  }
  return entries;
}

}  // namespace verity::validation
