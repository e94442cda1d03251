#include "validation/studies/npy_file.h"

#include <fmt/format.h>

#include <fstream>

#include "core/error.h"

namespace verity::studies {

void writeNpy(const std::filesystem::path& file, const std::vector<float>& data, int width,
              int height) {
  writeNpy(file, data.data(), data.size() * sizeof(float), "<f4", {size_t(height), size_t(width)});
}

void writeNpy(const std::filesystem::path& file, const void* data, size_t bytes,
              const std::string& descr, const std::vector<size_t>& shape) {
  // NPY format 1.0 (numpy.lib.format): magic, version, little-endian header length, then a
  // Python dict literal padded with spaces and a newline to a multiple of 64 bytes.
  std::string dims;
  for (size_t d : shape) dims += fmt::format("{}, ", d);
  if (!dims.empty()) dims.resize(dims.size() - (shape.size() > 1 ? 2 : 1));  // (3,), (2, 3)
  std::string header =
      fmt::format("{{'descr': '{}', 'fortran_order': False, 'shape': ({}), }}", descr, dims);
  const size_t total = 10 + header.size() + 1;
  header.append((64 - total % 64) % 64, ' ');
  header.push_back('\n');
  std::ofstream out(file, std::ios::binary);
  if (!out) throw VerityError(file.string(), "", "cannot write the file");
  out.write("\x93NUMPY\x01\x00", 8);
  const uint16_t length = uint16_t(header.size());
  const char lengthBytes[2] = {char(length & 0xff), char(length >> 8)};
  out.write(lengthBytes, 2);
  out.write(header.data(), std::streamsize(header.size()));
  out.write(static_cast<const char*>(data), std::streamsize(bytes));
}

}  // namespace verity::studies
