#pragma once
// KMR_ASAN is defined when this translation unit is built with AddressSanitizer (GCC defines
// __SANITIZE_ADDRESS__; clang answers __has_feature(address_sanitizer)).
#if defined(__SANITIZE_ADDRESS__)
#define KMR_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define KMR_ASAN 1
#endif
#endif
