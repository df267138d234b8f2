#pragma once
// Asserts for the core: on in debug and sanitizer builds (NDEBUG undefined), free in release.
// Setup code throws wiggle::Error instead; the hot loops only assert.
#include <cstdio>
#include <cstdlib>

#ifndef NDEBUG
#define WIGGLE_ASSERT(cond)                                                                \
  do {                                                                                     \
    if (!(cond)) {                                                                         \
      std::fprintf(stderr, "wiggle: assertion failed: %s (%s:%d)\n", #cond, __FILE__,     \
                   __LINE__);                                                              \
      std::abort();                                                                        \
    }                                                                                      \
  } while (0)
#else
#define WIGGLE_ASSERT(cond) ((void)0)
#endif
