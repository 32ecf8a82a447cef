// Whether this build has AddressSanitizer: gcc says so with
// __SANITIZE_ADDRESS__, clang through __has_feature. One answer for the code
// that must behave differently under it and for the tests that skip there.
#pragma once

namespace lbmshape {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool builtWithAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool builtWithAddressSanitizer = true;
#else
inline constexpr bool builtWithAddressSanitizer = false;
#endif
#else
inline constexpr bool builtWithAddressSanitizer = false;
#endif

}  // namespace lbmshape
