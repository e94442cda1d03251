#include "validation/studies/study_util.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <mutex>
#include <optional>
#include <sstream>
#include <thread>

#include "core/error.h"
#include "core/hash.h"

namespace verity::studies {

std::optional<nlohmann::json> sceneJsonAtWidth(const std::filesystem::path& file, int width) {
  std::ifstream in(file);
  if (!in) throw VerityError(file.string(), "", "cannot open the scene file");
  std::stringstream text;
  text << in.rdbuf();
  nlohmann::json scene;
  try {
    scene = nlohmann::json::parse(text.str());
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
  nlohmann::json& camera = scene["camera"];
  int w = 512, h = 512;  // the scene format's default resolution
  if (camera.contains("resolution") && camera["resolution"].is_array() &&
      camera["resolution"].size() == 2) {
    w = camera["resolution"][0].get<int>();
    h = camera["resolution"][1].get<int>();
  }
  const int height = std::max(1, int(std::lround(double(width) * h / std::max(w, 1))));
  camera["resolution"] = {width, height};
  return scene;
}

SceneFile loadStudyScene(const std::filesystem::path& file, int width) {
  if (width <= 0) return loadScene(file);
  const std::optional<nlohmann::json> scene = sceneJsonAtWidth(file, width);
  // A file that is not JSON: let the loader report the problem in its own words.
  return scene ? loadSceneText(scene->dump(), file) : loadScene(file);
}

std::vector<std::filesystem::path> shippedScenes(const std::filesystem::path& scenesDir) {
  std::vector<std::filesystem::path> scenes;
  for (const auto& folder : {scenesDir, scenesDir / "stress", scenesDir / "crosscheck"})
    for (const auto& entry : std::filesystem::directory_iterator(folder))
      if (entry.path().extension() == ".json") scenes.push_back(entry.path());
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

std::string shippedSceneName(const std::filesystem::path& file) {
  const std::string folder = file.parent_path().filename().string();
  const std::string name = file.stem().string();
  return folder == "stress" || folder == "crosscheck" ? folder + "/" + name : name;
}

IntegratorSettings studyIntegrator(const SceneFile& file, const std::string& type, int maxBounces) {
  IntegratorSettings settings = file.integrator;
  if (!type.empty()) {
    settings.type = canonicalIntegratorType(type);
    if (settings.type.empty())
      throw VerityError("", "--integrator", "unknown integrator type \"" + type + "\"");
  }
  if (maxBounces >= 0) settings.maxBounces = maxBounces;
  return settings;
}

uint64_t hashString(const std::string& s) {
  uint64_t h = 0xcbf29ce484222325ull;  // FNV-1a offset basis and prime (Fowler, Noll, Vo)
  for (unsigned char c : s) {
    h ^= c;
    h *= 0x100000001b3ull;
  }
  return h;
}

uint64_t runSeed(const std::string& integrator, const std::string& budgetType, double budget,
                 int run) {
  // The budget by its shortest decimal form, so that 0.1 s and 0.10 s give the same seed.
  return hashValues(hashString(integrator), hashString(budgetType),
                    hashString(fmt::format("{}", budget)), uint64_t(run));
}

namespace {

double cpuNow() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

}  // namespace

TimedRender timedRender(const SceneFile& file, const Integrator& integrator, Film& film, int spp,
                        int threads, uint64_t seed, double timeLimit, ComponentImages* components) {
  RenderOptions options;
  options.components = components;
  options.threads = threads;
  options.seed = seed;
  options.samplesPerPixel = timeLimit > 0 ? (1 << 24) : spp;
  std::atomic<bool> cancel{false};
  options.cancel = &cancel;
  std::unique_ptr<Sampler> sampler = file.sampler->clone();
  sampler->setSeed(seed);

  // With a time limit, a watchdog raises the cancel flag, which render() checks between
  // passes (so every pixel keeps the same sample count).
  std::mutex m;
  std::condition_variable cv;
  bool done = false;
  std::thread watchdog;
  TimedRender out;
  const double cpu0 = cpuNow();
  const auto wall0 = std::chrono::steady_clock::now();
  if (timeLimit > 0)
    watchdog = std::thread([&] {
      std::unique_lock lock(m);
      if (!cv.wait_for(lock, std::chrono::duration<double>(timeLimit), [&] { return done; }))
        cancel = true;
    });
  out.stats = render(*file.scene, integrator, *sampler, film, options);
  out.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  out.cpuSeconds = cpuNow() - cpu0;
  if (watchdog.joinable()) {
    {
      std::lock_guard lock(m);
      done = true;
    }
    cv.notify_all();
    watchdog.join();
  }
  return out;
}

uint64_t renderBatches(const SceneFile& file, const std::string& integrator, int maxBounces,
                       int batches, int spp, const std::string& key,
                       const std::function<void(const Film&)>& onBatch) {
  const auto render = makeIntegrator(studyIntegrator(file, integrator, maxBounces));
  uint64_t invalid = 0;
  for (int batch = 0; batch < batches; ++batch) {
    Film film(file.scene->camera().resolution());
    RenderOptions options;
    options.samplesPerPixel = spp;
    options.seed = hashString(fmt::format("{} batch {}", key, batch));
    file.sampler->setSeed(options.seed);
    invalid += verity::render(*file.scene, *render, *file.sampler, film, options).invalidSamples;
    onBatch(film);
  }
  return invalid;
}

MachineInfo machineInfo() {
  MachineInfo m;
  char host[256] = {};
  if (gethostname(host, sizeof host - 1) == 0) m.hostname = host;
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line))
    if (line.rfind("model name", 0) == 0) {
      const size_t colon = line.find(':');
      if (colon != std::string::npos)
        m.cpuModel = line.substr(line.find_first_not_of(" \t", colon + 1));
      break;
    }
  if (m.cpuModel.empty()) m.cpuModel = "unknown";
  m.cores = int(std::thread::hardware_concurrency());
  return m;
}

nlohmann::json toJson(const MachineInfo& m) {
  return {{"hostname", m.hostname}, {"cpu_model", m.cpuModel}, {"cores", m.cores}};
}

std::string sourceRevision() {
  // Read-only: rev-parse takes no lock and writes nothing.
  const std::string command =
      fmt::format("git -C '{}' rev-parse HEAD 2>/dev/null", VERITY_SOURCE_DIR);
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return "unknown";
  char buffer[128] = {};
  std::string out;
  while (fgets(buffer, sizeof buffer, pipe)) out += buffer;
  const int status = pclose(pipe);
  while (!out.empty() && std::isspace(static_cast<unsigned char>(out.back()))) out.pop_back();
  if (status != 0 || out.size() != 40) return "unknown";
  return out;
}

std::string timestamp() {
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  char buffer[64];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%S%z", &local);
  return buffer;
}

namespace {

const std::vector<float>& plane(const ImageChannels& image, const std::string& name) {
  const auto it = image.planes.find(name);
  if (it == image.planes.end())
    throw VerityError("", "", "the reference has no channel \"" + name + "\"");
  return it->second;
}

void checkSize(const Film& film, const ImageChannels& reference) {
  if (film.width() != reference.width || film.height() != reference.height)
    throw VerityError("", "",
                      fmt::format("the image is {}×{} but the reference is {}×{} (use the "
                                  "reference's resolution, or --resolution)",
                                  film.width(), film.height(), reference.width, reference.height));
}

}  // namespace

ErrorStats compareToReference(const Film& film, const ImageChannels& reference) {
  checkSize(film, reference);
  const std::vector<float>* ref[3] = {&plane(reference, "R"), &plane(reference, "G"),
                                      &plane(reference, "B")};
  ErrorStats s;
  double sumRel = 0, sumVar = 0, sumRelVar = 0;
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      const size_t i = size_t(y) * film.width() + x;
      const uint32_t n = film.count(x, y);
      const Color3 mean = film.mean(x, y);
      const Color3 var = film.sampleVariance(x, y);
      bool finite = n > 0;
      for (int c = 0; c < 3; ++c) finite = finite && std::isfinite((*ref[c])[i]);
      if (!finite) continue;
      for (int c = 0; c < 3; ++c) {
        const double r = (*ref[c])[i];
        const double denominator = r * r + kRelEpsilon;
        const double d = double(mean[c]) - r;
        const double varOfMean = double(var[c]) / n;
        sumRel += d * d / denominator;
        sumVar += varOfMean;
        sumRelVar += varOfMean / denominator;
      }
      ++s.pixelsUsed;
    }
  if (s.pixelsUsed == 0) return s;
  const double terms = 3.0 * double(s.pixelsUsed);
  s.relMse = sumRel / terms;
  s.meanVariance = sumVar / terms;
  s.relVariance = sumRelVar / terms;
  return s;
}

std::vector<float> relativeErrorImage(const Film& film, const ImageChannels& reference) {
  checkSize(film, reference);
  const std::vector<float>* ref[3] = {&plane(reference, "R"), &plane(reference, "G"),
                                      &plane(reference, "B")};
  std::vector<float> out(size_t(film.width()) * film.height());
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      const size_t i = size_t(y) * film.width() + x;
      const Color3 mean = film.mean(x, y);
      double sum = 0;
      for (int c = 0; c < 3; ++c) {
        const double r = (*ref[c])[i];
        const double d = double(mean[c]) - r;
        sum += d * d / (r * r + kRelEpsilon);
      }
      out[i] = float(std::sqrt(sum / 3));
    }
  return out;
}

double referenceRelMse(const ImageChannels& reference) {
  const std::vector<float>& samples = plane(reference, "samples");
  double sum = 0;
  size_t terms = 0;
  for (const char* c : {"R", "G", "B"}) {
    const std::vector<float>& mean = plane(reference, c);
    const std::vector<float>& var = plane(reference, std::string("variance.") + c);
    for (size_t i = 0; i < mean.size(); ++i) {
      if (!(samples[i] > 0) || !std::isfinite(mean[i]) || !std::isfinite(var[i])) continue;
      sum += double(var[i]) / samples[i] / (double(mean[i]) * mean[i] + kRelEpsilon);
      ++terms;
    }
  }
  return terms ? sum / double(terms) : 0;
}

void writeNpy(const std::filesystem::path& file, const std::vector<float>& data, int width,
              int height) {
  // NPY format 1.0 (numpy.lib.format): magic, version, little-endian header length, then a
  // Python dict literal padded with spaces and a newline to a multiple of 64 bytes.
  std::string header =
      fmt::format("{{'descr': '<f4', 'fortran_order': False, 'shape': ({}, {}), }}", height, width);
  const size_t total = 10 + header.size() + 1;
  header.append((64 - total % 64) % 64, ' ');
  header.push_back('\n');
  std::ofstream out(file, std::ios::binary);
  if (!out) throw VerityError(file.string(), "", "cannot write the file");
  out.write("\x93NUMPY\x01\x00", 8);
  const uint16_t length = uint16_t(header.size());
  const char lengthBytes[2] = {char(length & 0xff), char(length >> 8)};
  out.write(lengthBytes, 2);
  out.write(header.data(), std::streamsize(header.size()));
  out.write(reinterpret_cast<const char*>(data.data()),
            std::streamsize(data.size() * sizeof(float)));
}

std::vector<nlohmann::json> readJsonLines(const std::filesystem::path& file) {
  std::vector<nlohmann::json> records;
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    try {
      nlohmann::json j = nlohmann::json::parse(line);
      if (j.is_object()) records.push_back(std::move(j));
    } catch (const nlohmann::json::exception&) {
      // a line cut off by an interruption: that run is simply redone
    }
  }
  return records;
}

void appendJsonLine(const std::filesystem::path& file, const nlohmann::json& record) {
  // A torn last line (the process killed mid-write) must not glue onto this record.
  bool needNewline = false;
  {
    std::ifstream in(file, std::ios::binary | std::ios::ate);
    if (in && in.tellg() > 0) {
      in.seekg(-1, std::ios::end);
      needNewline = in.get() != '\n';
    }
  }
  std::ofstream out(file, std::ios::app);
  if (!out) throw VerityError(file.string(), "", "cannot append to the results file");
  if (needNewline) out << '\n';
  out << record.dump() << '\n';
  out.flush();
  if (!out) throw VerityError(file.string(), "", "cannot write to the results file");
}

}  // namespace verity::studies
