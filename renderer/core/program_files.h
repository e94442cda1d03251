// Files the `verity` program runs besides itself, found at run time so that an installed
// program works wherever it is installed: the Python helper scripts it ships and the python3
// that runs them.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace verity {

// <prefix>/share/verity/<name> for a program running as <prefix>/bin/<program>. The build
// tree has the same layout (<build>/bin and <build>/share/verity, where the build copies the
// scripts). Throws VerityError naming the path looked for when the file is not there.
std::filesystem::path sharedProgramFile(const std::string& name);

// The first executable `program` in the directories of PATH; empty when there is none.
std::filesystem::path findOnPath(const std::string& program);

// The Python that runs the shipped scripts: one that can import `module` (matplotlib). Tries
// $VERITY_PYTHON alone when it is set, else `python3` on PATH, then Debian's /usr/bin/python3
// (where python3-matplotlib installs; a python3 of pyenv or a virtual environment may come
// first on PATH without it). Throws VerityError naming `purpose` and every interpreter tried.
std::filesystem::path findPythonWith(const std::string& module, const std::string& purpose);

// Runs `args` (no shell, so no quoting) and returns its exit status, or −1 if it could not be
// started or was killed. `quiet`: its standard output and error go to /dev/null.
int runProgram(std::vector<std::string> args, bool quiet = false);

}  // namespace verity
