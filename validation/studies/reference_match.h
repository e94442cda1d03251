// Whether a reference image is one of the scene a study renders, at the study's resolution:
// errors measured against another scene's reference mean nothing, and per-pixel errors need
// the same pixels.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include "core/math.h"
#include "film/image_io.h"

namespace verity::studies {

// Throws VerityError naming `file` when `image` holds a value that is not finite: the channel,
// the pixel and the value, then `consequence`.
void refuseNonFinite(const ImageChannels& image, const std::filesystem::path& file,
                     const std::string& consequence);

// Throws VerityError naming the reference when it holds a value that is not finite, when its
// size differs from `resolution` (advising to leave out --resolution only when
// `resolutionGiven`), or when the scene it records (the verity:scene attribute) is not `scene`;
// with `force` a different scene is only reported to `log`. A reference that records no scene is
// reported to `log`. Scenes are the same file when both paths name one, else when their names
// (stems) agree.
void checkReferenceMatches(const std::filesystem::path& referenceFile,
                           const ImageChannels& reference, const std::filesystem::path& scene,
                           const Vector2i& resolution, bool resolutionGiven, bool force,
                           const std::function<void(const std::string&)>& log);

}  // namespace verity::studies
