// hashString is 64-bit FNV-1a: the published test vectors of its authors (Fowler, Noll and Vo),
// so that every seed fixed by name stays what it was.
#include "core/hash.h"

#include <gtest/gtest.h>

namespace verity {
namespace {

TEST(HashString, IsFnv1a) {
  EXPECT_EQ(hashString(""), 0xcbf29ce484222325ull);
  EXPECT_EQ(hashString("a"), 0xaf63dc4c8601ec8cull);
  EXPECT_EQ(hashString("foobar"), 0x85944171f73967e8ull);
}

}  // namespace
}  // namespace verity
