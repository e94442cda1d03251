// Where the referee's renders come from: a renderer run as a process per render
// (process_render_source.h), or, in tests, images made in the process by the same generator a
// fake renderer program writes, so that hundreds of refereed decisions take seconds.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <stdexcept>
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

// Thrown by a source when the user interrupted the renders (Ctrl-C): not a verdict, not bad
// input.
class RendersInterrupted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Thrown by a source when the time budget (--max-seconds) ended while renders were running:
// they were stopped, and the round they belonged to decides nothing.
class RenderBudgetEnded : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// When the renders in flight must be stopped; none: no limit.
using RenderDeadline = std::optional<std::chrono::steady_clock::time_point>;

class RenderSource {
 public:
  virtual ~RenderSource() = default;
  // One image per request, in the requests' order. Throws VerityError when a render fails,
  // RendersInterrupted when the user interrupted them, RenderBudgetEnded when `deadline`
  // passed before they were done.
  virtual std::vector<Rendered> render(const std::vector<RenderRequest>& requests,
                                       RenderDeadline deadline) = 0;
};

}  // namespace verity::validation
