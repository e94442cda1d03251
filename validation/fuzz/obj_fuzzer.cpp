// libFuzzer target: any bytes given to the OBJ reader end in a mesh or a VerityError.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/error.h"
#include "shapes/obj_loader.h"
#include "shapes/triangle_mesh.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const verity::MeshData mesh =
        verity::parseObj(text, "fuzzed.obj", verity::Transform(), "filename");
    const verity::TriangleMesh shape(mesh);  // areas, sampling tables
    (void)shape.area();
  } catch (const verity::VerityError&) {
  }
  return 0;
}
