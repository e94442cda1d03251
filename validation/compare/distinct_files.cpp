#include "validation/compare/distinct_files.h"

#include <fmt/format.h>

#include <fstream>
#include <functional>
#include <iterator>
#include <string>

#include "core/error.h"

namespace verity::validation {

namespace {

std::string contents(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw VerityError(file.string(), "", "cannot read the file");
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace

void requireDistinctFiles(const std::vector<std::filesystem::path>& files) {
  for (const std::filesystem::path& f : files)
    if (!std::filesystem::is_regular_file(f)) throw VerityError(f.string(), "", "no such file");
  // Each file read once for its digest; only files with equal digests are compared whole.
  std::vector<size_t> digests;
  for (const std::filesystem::path& f : files)
    digests.push_back(std::hash<std::string>{}(contents(f)));
  for (size_t i = 0; i < files.size(); ++i)
    for (size_t j = i + 1; j < files.size(); ++j) {
      if (std::filesystem::equivalent(files[i], files[j]))
        throw VerityError(files[j].string(), "",
                          fmt::format("is the same file as \"{}\": each render may be given "
                                      "once",
                                      files[i].string()));
      if (digests[i] == digests[j] && contents(files[i]) == contents(files[j]))
        throw VerityError(files[j].string(), "",
                          fmt::format("has the same bytes as \"{}\": a copy of one render is "
                                      "not an independent render",
                                      files[i].string()));
    }
}

}  // namespace verity::validation
