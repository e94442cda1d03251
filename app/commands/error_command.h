// `verity error --reference REF.exr IMAGE.exr ...`: the relative MSE of renders from any
// renderer against a reference, by the studies' formula (relative_error.h), so that another
// renderer's error per sample and efficiency are measured as `verity bench --reference`
// measures ours (scripts/peer_efficiency times the renders).
#pragma once

#include <CLI/CLI.hpp>

#include "distributed/process_group.h"

namespace verity {

void addErrorCommand(CLI::App& app, const ProcessGroup& group);

}  // namespace verity
