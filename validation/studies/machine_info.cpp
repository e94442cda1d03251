#include "validation/studies/machine_info.h"

#include <fmt/format.h>
#include <unistd.h>

#include <ctime>
#include <fstream>
#include <thread>

namespace verity::studies {

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

std::string timestamp() {
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  char buffer[64];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%S%z", &local);
  return buffer;
}

}  // namespace verity::studies
