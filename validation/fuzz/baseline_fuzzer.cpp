// libFuzzer target: any bytes given to the referee's baseline reader end in a baseline or a
// VerityError naming the file.
#include "validation/fuzz/referee_file_fuzzer.h"
#include "validation/referee/baseline.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return verity::fuzz::readFuzzedFile(data, size, "baseline-fuzz", [](const auto& file) {
    verity::validation::loadBaseline(file);
  });
}
