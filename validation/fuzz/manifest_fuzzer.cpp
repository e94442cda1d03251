// libFuzzer target: any bytes given to the referee's manifest reader end in its entries or a
// VerityError naming the file and the JSON path.
#include "validation/fuzz/referee_file_fuzzer.h"
#include "validation/referee/manifest.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return verity::fuzz::readFuzzedFile(data, size, "manifest-fuzz", [](const auto& file) {
    verity::validation::loadManifest(file);
  });
}
