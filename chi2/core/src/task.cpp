#include "task.h"

#include <array>
#include <new>
#include <utility>

namespace verity::chi2 {

namespace {

constexpr std::size_t kGranule = 64, kClasses = 32;  // frames up to 2 KiB are pooled
constexpr std::size_t kKeptPerClass = 1 << 14;       // beyond this a freed frame goes back

// A freed frame holds the next free one of its size.
struct FreeFrame {
  FreeFrame* next;
};

struct FreeLists {
  std::array<FreeFrame*, kClasses> head{};
  std::array<std::size_t, kClasses> count{};
  ~FreeLists() {
    for (FreeFrame* f : head)
      while (f) ::operator delete(std::exchange(f, f->next));
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
  FreeLists& lists = freeLists;
  FreeFrame* frame = lists.head[c];
  if (!frame) return ::operator new(c* kGranule);
  lists.head[c] = frame->next;
  --lists.count[c];
  return frame;
}

void freeFrame(void* frame, std::size_t size) noexcept {
  const std::size_t c = sizeClass(size);
  FreeLists& lists = freeLists;
  if (c >= kClasses || lists.count[c] >= kKeptPerClass) return ::operator delete(frame);
  lists.head[c] = new (frame) FreeFrame{lists.head[c]};
  ++lists.count[c];
}

}  // namespace verity::chi2
