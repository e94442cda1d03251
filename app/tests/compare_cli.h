// Runs `verity compare ARGS...` through the command's own parser, as the program runs it,
// and keeps its exit status and what it printed.
#pragma once

#include <gtest/gtest.h>

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "commands/compare_command.h"
#include "distributed/process_group.h"

namespace verity::validation::testing {

struct CompareOutcome {
  int status = -1;  // 0 agree, 1 differ, 2 bad input (a command line that cannot be parsed too)
  std::string out, err;

  std::string text() const { return "status " + std::to_string(status) + "\n" + out + err; }
};

inline CompareOutcome runCompare(const std::vector<std::string>& args) {
  CLI::App app;
  addCompareCommand(app, ProcessGroup::solo());
  std::vector<std::string> words = {"verity", "compare"};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<const char*> argv;
  for (const std::string& w : words) argv.push_back(w.c_str());
  CompareOutcome o;
  std::string parseError;
  ::testing::internal::CaptureStdout();
  ::testing::internal::CaptureStderr();
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
    o.status = 0;
  } catch (const CLI::RuntimeError& e) {
    o.status = e.get_exit_code();
  } catch (const CLI::ParseError& e) {
    // As the program reports it (app/main.cpp): the message on stderr and status 2.
    o.status = 2;
    parseError = std::string(e.what()) + "\n";
  }
  o.out = ::testing::internal::GetCapturedStdout();
  o.err = ::testing::internal::GetCapturedStderr() + parseError;
  return o;
}

// "-a A... -b B...".
inline std::vector<std::string> sideArguments(const std::vector<std::string>& a,
                                              const std::vector<std::string>& b) {
  std::vector<std::string> args = {"-a"};
  args.insert(args.end(), a.begin(), a.end());
  args.push_back("-b");
  args.insert(args.end(), b.begin(), b.end());
  return args;
}

}  // namespace verity::validation::testing
