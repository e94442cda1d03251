// A computation that may wait for values: a C++20 coroutine returning T, started when it is
// awaited (or run: density.h), so that the quadrature and the partition are written once, as
// recursions, and run either at once, point by point, or interleaved with every other
// computation waiting for the same batch of density values.
#pragma once

#include <coroutine>
#include <cstddef>
#include <exception>
#include <optional>
#include <utility>

namespace verity::chi2 {

// Coroutine frames come and go by the million in a quadrature (one per rule, and per piece
// bisected): they are kept on per-thread free lists by size rather than returned to malloc,
// which otherwise took a fifth of the point-by-point quadrature's time.
void* allocateFrame(std::size_t size);
void freeFrame(void* frame, std::size_t size) noexcept;

// Children awaited together (Density::all): the last to finish resumes their parent.
struct Join {
  size_t remaining = 0;
  std::coroutine_handle<> parent;
  const std::coroutine_handle<>* next = nullptr;  // [next, end): not yet started
  const std::coroutine_handle<>* end = nullptr;
};

template <class T>
class Task {
 public:
  struct promise_type {
    std::optional<T> value;
    std::exception_ptr error;
    std::coroutine_handle<> continuation;  // the computation awaiting this one
    Join* join = nullptr;                  // or the children this one was started with

    Task get_return_object() { return Task(Handle::from_promise(*this)); }
    std::suspend_always initial_suspend() noexcept { return {}; }
    struct Final {
      bool await_ready() noexcept { return false; }
      // Symmetric transfer to whoever waits, so that a deep recursion does not grow the stack.
      std::coroutine_handle<> await_suspend(std::coroutine_handle<promise_type> h) noexcept {
        promise_type& p = h.promise();
        if (Join* j = p.join) return --j->remaining == 0 ? j->parent : std::noop_coroutine();
        return p.continuation ? p.continuation : std::noop_coroutine();
      }
      void await_resume() noexcept {}
    };
    Final final_suspend() noexcept { return {}; }
    template <class U>
    void return_value(U&& v) {
      value.emplace(std::forward<U>(v));
    }
    void unhandled_exception() { error = std::current_exception(); }
    static void* operator new(std::size_t size) { return allocateFrame(size); }
    static void operator delete(void* frame, std::size_t size) noexcept { freeFrame(frame, size); }
  };
  using Handle = std::coroutine_handle<promise_type>;

  Task(Task&& o) noexcept : handle_(std::exchange(o.handle_, {})) {}
  Task& operator=(Task&& o) noexcept {
    if (this != &o) {
      if (handle_) handle_.destroy();
      handle_ = std::exchange(o.handle_, {});
    }
    return *this;
  }
  Task(const Task&) = delete;
  Task& operator=(const Task&) = delete;
  ~Task() {
    if (handle_) handle_.destroy();
  }

  // co_await task: starts it; the awaiting computation resumes with its result.
  bool await_ready() const noexcept { return false; }
  std::coroutine_handle<> await_suspend(std::coroutine_handle<> awaiting) noexcept {
    handle_.promise().continuation = awaiting;
    return handle_;
  }
  T await_resume() { return result(); }

  Handle handle() const { return handle_; }
  // The finished computation's result; what it threw is thrown again here.
  T result() {
    promise_type& p = handle_.promise();
    if (p.error) std::rethrow_exception(p.error);
    return std::move(*p.value);
  }

 private:
  explicit Task(Handle h) : handle_(h) {}
  Handle handle_;
};

}  // namespace verity::chi2
