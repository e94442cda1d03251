// VERITY_TEST_THREADS=n caps oneTBB at n threads for the whole process. CTest sets it to 1
// for every test of this executable (chi2/suite/CMakeLists.txt): `ctest -j` already runs one
// of them on every core, and two threads per test on a 2-core machine only contend (a sample
// of the sweep's configurations ran 3 to 5% faster so). A check's result does not depend on its
// threads (chi2.ThreadCount), so the cap changes only the time.
#include <tbb/global_control.h>

#include <cstdio>
#include <cstdlib>
#include <memory>

namespace {

std::unique_ptr<tbb::global_control> capFromEnvironment() {
  const char* value = std::getenv("VERITY_TEST_THREADS");
  if (!value) return nullptr;
  char* end = nullptr;
  const long threads = std::strtol(value, &end, 10);
  if (end == value || *end != '\0' || threads < 1) {
    std::fprintf(stderr, "VERITY_TEST_THREADS: '%s' is not a thread count of at least 1\n", value);
    std::exit(2);
  }
  return std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                               static_cast<size_t>(threads));
}

// Made before main(), so before any test's first parallel loop.
const std::unique_ptr<tbb::global_control> kThreadCap = capFromEnvironment();

}  // namespace
