// Where the referee's renders come from: a renderer run as a process per render
// (process_render_source.h), or, in tests, images made in the process by the same generator a
// fake renderer program writes, so that hundreds of refereed decisions take seconds.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "film/image_io.h"

namespace verity::validation {

enum class Side { A = 0, B = 1 };

struct RenderRequest {
  Side side = Side::A;
  uint64_t seed = 0;
};

struct Rendered {
  ImageChannels image;
  std::string label;  // names the render in errors (its file)
};

class RenderSource {
 public:
  virtual ~RenderSource() = default;
  // One image per request, in the requests' order. Throws VerityError when a render fails.
  virtual std::vector<Rendered> render(const std::vector<RenderRequest>& requests) = 0;
};

}  // namespace verity::validation
