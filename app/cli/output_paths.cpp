#include "cli/output_paths.h"

#include <unistd.h>

#include <fstream>

#include "core/error.h"

namespace verity {

void prepareOutputFolder(const std::filesystem::path& folder, const std::string& option) {
  if (folder.empty()) return;  // the current directory
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error || !std::filesystem::is_directory(folder))
    throw VerityError("", option,
                      "cannot create the folder \"" + folder.string() + "\"" +
                          (error ? " (" + error.message() + ")" : ""));
  if (access(folder.c_str(), W_OK) != 0)
    throw VerityError("", option, "cannot write in the folder \"" + folder.string() + "\"");
}

void prepareOutputFile(const std::filesystem::path& file, const std::string& option) {
  const std::filesystem::path folder = file.parent_path();
  prepareOutputFolder(folder, option);
  // A probe file beside it: permission bits alone do not tell, for instance for root.
  const std::filesystem::path probe = file.string() + ".verity-probe";
  if (!std::ofstream(probe))
    throw VerityError(
        "", option, "cannot create files in \"" + (folder.empty() ? "." : folder.string()) + "\"");
  std::error_code error;
  std::filesystem::remove(probe, error);
}

}  // namespace verity
