#pragma once
// Whether this test binary runs under a sanitizer (./sylva test --sanitize ...): ASan reserves
// terabytes of address space (so `ulimit -v` cannot bound it) and quarantines freed memory (so
// resident memory grows by design); tests that measure either skip that part then.
namespace sylva::testing {

#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
inline constexpr bool k_sanitized = true;
#else
inline constexpr bool k_sanitized = false;
#endif
#elif defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
inline constexpr bool k_sanitized = true;
#else
inline constexpr bool k_sanitized = false;
#endif

}  // namespace sylva::testing
