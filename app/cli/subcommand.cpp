#include "cli/subcommand.h"

#include <fmt/format.h>

#include "core/error.h"

namespace verity {

namespace {

// "study strategies" for a command under "study"; the program's own name is left out.
std::string commandPath(const CLI::App* command) {
  std::string path = command->get_name();
  for (const CLI::App* p = command->get_parent(); p && p->get_parent(); p = p->get_parent())
    path = p->get_name() + " " + path;
  return path;
}

}  // namespace

CLI::App* addSubcommand(CLI::App& parent, const std::string& name, const std::string& description,
                        MpiUse use, const ProcessGroup& group) {
  CLI::App* command = parent.add_subcommand(name, description);
  if (use == MpiUse::OneProcess)
    command->preparse_callback([command, &group](size_t) {
      if (group.distributed())
        throw VerityError("", "verity " + commandPath(command),
                          fmt::format("runs in one process and does not split its work over MPI "
                                      "ranks; run it without mpirun (this job has {} ranks)",
                                      group.size()));
    });
  return command;
}

}  // namespace verity
