// Where the `verity` commands write. One rule for every command: a missing folder on the way to
// an output (or an output folder itself) is created, as `mkdir -p` would; a path that runs
// through a file, or a folder that cannot be written, is an error that names the option, given
// before any work starts.
#pragma once

#include <filesystem>
#include <string>

namespace verity {

// Makes the folder that will hold the output file `file` (given with `option`), and checks
// that a file can be created there.
void prepareOutputFile(const std::filesystem::path& file, const std::string& option);

// Makes the output folder `folder` (given with `option`), and checks that it can be written.
void prepareOutputFolder(const std::filesystem::path& folder, const std::string& option);

}  // namespace verity
