#include "validation/studies/npy_file.h"

#include <fmt/format.h>

#include <Eigen/Core>
#include <cstdint>
#include <fstream>
#include <string>

#include "core/error.h"

namespace verity::studies {

void writeHalfNpy(const std::filesystem::path& file, const std::vector<float>& values,
                  const std::vector<size_t>& shape) {
  // NPY format 1.0 (numpy.lib.format): magic, version, little-endian header length, then a
  // Python dict literal padded with spaces and a newline to a multiple of 64 bytes.
  std::string dims;
  for (size_t d : shape) dims += fmt::format("{}, ", d);
  if (!dims.empty()) dims.resize(dims.size() - (shape.size() > 1 ? 2 : 1));  // (3,), (2, 3)
  std::string header =
      fmt::format("{{'descr': '<f2', 'fortran_order': False, 'shape': ({}), }}", dims);
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
  std::vector<uint16_t> halves;
  halves.reserve(values.size());
  for (float v : values) halves.push_back(Eigen::numext::bit_cast<uint16_t>(Eigen::half(v)));
  out.write(reinterpret_cast<const char*>(halves.data()),
            std::streamsize(halves.size() * sizeof(uint16_t)));
}

}  // namespace verity::studies
