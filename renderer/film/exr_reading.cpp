// readExr, apart from the rest of image_io.cpp: built alone and position-independent
// (verity_exr_reading), so that the Python module reads renders for verity.compare with the
// very code `verity compare` runs, without linking the renderer.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfStringAttribute.h>

#include "core/error.h"
#include "film/image_io.h"

namespace verity {

ImageChannels readExr(const std::filesystem::path& file) {
  try {
    Imf::InputFile in(file.string().c_str());
    const auto& header = in.header();
    const auto dw = header.dataWindow();
    ImageChannels image;
    image.width = dw.max.x - dw.min.x + 1;
    image.height = dw.max.y - dw.min.y + 1;
    Imf::FrameBuffer frame;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
      auto& plane = image.planes[it.name()];
      plane.assign(size_t(image.width) * image.height, 0.0f);
      char* base = reinterpret_cast<char*>(plane.data()) -
                   (dw.min.x + size_t(dw.min.y) * image.width) * sizeof(float);
      frame.insert(it.name(),
                   Imf::Slice(Imf::FLOAT, base, sizeof(float), sizeof(float) * image.width));
    }
    for (auto it = header.begin(); it != header.end(); ++it)
      if (const auto* s = dynamic_cast<const Imf::StringAttribute*>(&it.attribute()))
        image.attributes[it.name()] = s->value();
    in.setFrameBuffer(frame);
    in.readPixels(dw.min.y, dw.max.y);
    return image;
  } catch (const std::exception& e) {
    throw VerityError(file.string(), "", std::string("cannot read OpenEXR image: ") + e.what());
  }
}

}  // namespace verity
