// libFuzzer target: any bytes given to the scene loader end in a scene or a VerityError,
// never a crash, a hang or undefined behaviour. Relative file names resolve against
// scenes/malformed/, whose meshes and images are broken on purpose.
#include <cstddef>
#include <cstdint>
#include <string>

#include "loader/scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    verity::loadSceneText(text, VERITY_SOURCE_DIR "/scenes/malformed/fuzzed.json");
  } catch (const verity::VerityError&) {
  }
  return 0;
}
