// The referee's file readers under libFuzzer: the bytes go to a file of their own (the readers
// take paths, and name them in their errors), which `read` reads; a VerityError is the one
// way out besides success: never a crash, a hang or undefined behaviour.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>

#include "core/error.h"

namespace verity::fuzz {

template <class Read>
int readFuzzedFile(const uint8_t* data, size_t size, const char* name, Read read) {
  // One file per process: libFuzzer runs its inputs one after another.
  static const std::filesystem::path file =
      std::filesystem::temp_directory_path() /
      (std::string(name) + "-" + std::to_string(getpid()) + ".json");
  if (FILE* f = std::fopen(file.c_str(), "wb")) {
    std::fwrite(data, 1, size, f);
    std::fclose(f);
  }
  try {
    read(file);
  } catch (const VerityError&) {
  }
  return 0;
}

}  // namespace verity::fuzz
