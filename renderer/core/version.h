// The program's version and the git revision it was built from, written at build time into a
// generated revision.cpp (app/write_revision.cmake), the whole of the small library
// verity_version: a new commit recompiles that one file and relinks what links it (the
// program and the studies, whose records name the revision), nothing else.
#pragma once

namespace verity {

extern const char* const kVersion;   // the project's version, e.g. "0.1.0"
extern const char* const kRevision;  // 12 hex digits of the commit, or "unknown" outside git

}  // namespace verity
