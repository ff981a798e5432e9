// ISOPARM_ASAN is defined where this translation unit is built with AddressSanitizer (GCC's
// -fsanitize=address or clang's): the few places that must act differently under it (a forked
// reader that should die of its own signal, GL drivers kept loaded for LeakSanitizer) ask it.
#pragma once

#if defined(__SANITIZE_ADDRESS__)
#define ISOPARM_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define ISOPARM_ASAN 1
#endif
#endif
