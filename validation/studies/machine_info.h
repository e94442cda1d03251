// What a study record says about where and from what it was made: host, CPU, cores, source
// revision and time.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace verity::studies {

struct MachineInfo {
  std::string hostname, cpuModel;
  int cores = 0;
};
MachineInfo machineInfo();
nlohmann::json toJson(const MachineInfo& m);
// `git rev-parse HEAD` of the source tree, or "unknown".
std::string sourceRevision();
// The local time as ISO 8601.
std::string timestamp();

}  // namespace verity::studies
