#pragma once
/// \file
/// MESHEDIT_ASSERT: programmer errors only (an invalid or deleted handle, a broken
/// precondition that user input cannot reach). User-reachable conditions are checked by
/// predicates and reported, never asserted.

#include <cstdio>
#include <cstdlib>

#ifdef NDEBUG
#define MESHEDIT_ASSERT(cond) ((void)0)
#else
#define MESHEDIT_ASSERT(cond)                                                                    \
    ((cond) ? (void)0                                                                            \
            : (std::fprintf(stderr, "%s:%d: assertion failed: %s\n", __FILE__, __LINE__, #cond), \
               std::abort()))
#endif
