#include "film/image_io.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>
#include <fmt/format.h>
#include <stb_image_write.h>

#include <cmath>

#include "core/error.h"
#include "film/srgb.h"

namespace verity {

ImageChannels filmChannels(const Film& film, bool withVariance) {
  ImageChannels image;
  image.width = film.width();
  image.height = film.height();
  const size_t n = size_t(image.width) * image.height;
  const char* rgb[3] = {"R", "G", "B"};
  const char* var[3] = {"variance.R", "variance.G", "variance.B"};
  for (int c = 0; c < 3; ++c) {
    image.planes[rgb[c]].resize(n);
    if (withVariance) image.planes[var[c]].resize(n);
  }
  if (withVariance) image.planes["samples"].resize(n);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const size_t i = size_t(y) * image.width + x;
      const Color3 m = film.mean(x, y);
      for (int c = 0; c < 3; ++c) image.planes[rgb[c]][i] = m[c];
      if (withVariance) {
        const Color3 v = film.sampleVariance(x, y);
        for (int c = 0; c < 3; ++c) image.planes[var[c]][i] = v[c];
        image.planes["samples"][i] = static_cast<float>(film.count(x, y));
      }
    }
  }
  return image;
}

namespace {

bool storedAsHalf(const std::string& plane, bool halfFloat) {
  return halfFloat && plane != "samples";
}

// Refuses the first value a half-float plane would store as Inf (or a NaN it would keep).
void checkHalfRange(const std::filesystem::path& file, const ImageChannels& image) {
  for (const auto& [name, plane] : image.planes) {
    if (!storedAsHalf(name, true)) continue;
    for (size_t i = 0; i < plane.size(); ++i)
      if (!(std::fabs(plane[i]) <= kHalfFloatMax))
        throw VerityError(file.string(), "",
                          fmt::format("channel {} at pixel ({}, {}) holds {}, beyond the range of "
                                      "half floats (±{})",
                                      name, i % size_t(image.width), i / size_t(image.width),
                                      plane[i], kHalfFloatMax));
  }
}

}  // namespace

bool fitsHalfFloat(const ImageChannels& image) {
  for (const auto& [name, plane] : image.planes) {
    if (!storedAsHalf(name, true)) continue;
    for (float v : plane)
      if (!(std::fabs(v) <= kHalfFloatMax)) return false;
  }
  return true;
}

void writeExr(const std::filesystem::path& file, const ImageChannels& image, bool halfFloat) {
  if (halfFloat) checkHalfRange(file, image);
  try {
    Imf::Header header(image.width, image.height);
    header.compression() = Imf::ZIP_COMPRESSION;
    for (const auto& [key, value] : image.attributes)
      header.insert(key, Imf::StringAttribute(value));
    Imf::FrameBuffer frame;
    std::vector<std::vector<half>> halves;
    halves.reserve(image.planes.size());
    for (const auto& [name, plane] : image.planes) {
      const bool asHalf = storedAsHalf(name, halfFloat);
      header.channels().insert(name, Imf::Channel(asHalf ? Imf::HALF : Imf::FLOAT));
      if (asHalf) {
        halves.emplace_back(plane.begin(), plane.end());
        frame.insert(name, Imf::Slice(Imf::HALF, reinterpret_cast<char*>(halves.back().data()),
                                      sizeof(half), sizeof(half) * image.width));
      } else {
        frame.insert(
            name,
            Imf::Slice(Imf::FLOAT, const_cast<char*>(reinterpret_cast<const char*>(plane.data())),
                       sizeof(float), sizeof(float) * image.width));
      }
    }
    Imf::OutputFile out(file.string().c_str(), header);
    out.setFrameBuffer(frame);
    out.writePixels(image.height);
  } catch (const std::exception& e) {
    throw VerityError(file.string(), "", std::string("cannot write OpenEXR image: ") + e.what());
  }
}

void writePng(const std::filesystem::path& file, const ImageChannels& image) {
  const char* names[3] = {"R", "G", "B"};
  std::vector<unsigned char> bytes(size_t(image.width) * image.height * 3);
  for (int c = 0; c < 3; ++c) {
    auto it = image.planes.find(names[c]);
    if (it == image.planes.end()) throw VerityError(file.string(), "", "image has no RGB channels");
    for (size_t i = 0; i < it->second.size(); ++i) {
      const float v = linearToSrgb(std::clamp(it->second[i], 0.0f, 1.0f));
      bytes[3 * i + c] = static_cast<unsigned char>(std::clamp(v * 255.0f + 0.5f, 0.0f, 255.0f));
    }
  }
  if (!stbi_write_png(file.string().c_str(), image.width, image.height, 3, bytes.data(),
                      image.width * 3))
    throw VerityError(file.string(), "", "cannot write PNG image");
}

}  // namespace verity
