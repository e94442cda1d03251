// What a study record says about where and when it was made: host, CPU, cores and time (the
// revision it was made from is the build's, core/version.h).
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
// The local time as ISO 8601.
std::string timestamp();

}  // namespace verity::studies
