#include "task.h"

#include <array>
#include <new>
#include <vector>

namespace verity::chi2 {

namespace {

constexpr std::size_t kGranule = 64, kClasses = 32;  // frames up to 2 KiB are pooled
constexpr std::size_t kKeptPerClass = 1 << 14;       // beyond this a freed frame goes back

struct FreeLists {
  std::array<std::vector<void*>, kClasses> lists;
  ~FreeLists() {
    for (auto& list : lists)
      for (void* frame : list) ::operator delete(frame);
  }
};
thread_local FreeLists freeLists;

std::size_t sizeClass(std::size_t size) {
  return (size + kGranule - 1) / kGranule;
}

}  // namespace

void* allocateFrame(std::size_t size) {
  const std::size_t c = sizeClass(size);
  if (c >= kClasses) return ::operator new(size);
  std::vector<void*>& list = freeLists.lists[c];
  if (list.empty()) return ::operator new(c* kGranule);
  void* frame = list.back();
  list.pop_back();
  return frame;
}

void freeFrame(void* frame, std::size_t size) noexcept {
  const std::size_t c = sizeClass(size);
  if (c >= kClasses) return ::operator delete(frame);
  std::vector<void*>& list = freeLists.lists[c];
  if (list.size() >= kKeptPerClass) return ::operator delete(frame);
  try {
    list.push_back(frame);
  } catch (const std::bad_alloc&) {
    ::operator delete(frame);
  }
}

}  // namespace verity::chi2
