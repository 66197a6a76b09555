// Per-thread scratch buffers for hot paths that must not allocate once warmed up.
#pragma once

namespace crowdsim {

/// This thread's T for `Tag`, built on first use and destroyed at the thread's exit. Tag: a
/// type of the caller's own (a local struct), so that no two callers share an object. Reached
/// through a plain pointer (one TLS lookup, not a guard's and the object's) behind a call: inlined,
/// GCC re-derives a shared object's thread-local address after every call its caller makes (each
/// push_back, say).
template <class T, class Tag = T>
[[gnu::noinline]] T& ThreadScratch() {
  thread_local T* scratch = nullptr;
  if (scratch == nullptr) {
    thread_local T object;
    scratch = &object;
  }
  return *scratch;
}

}  // namespace crowdsim
