// MIRAGE_CHECK: invariants checked where they are born (a NaN in a path is a bug here,
// not three modules later).  Always on: the checks sit outside the hot loops.
#pragma once

#include <cstdio>
#include <cstdlib>

#define MIRAGE_CHECK(cond)                                                                        \
    do {                                                                                          \
        if (!(cond)) {                                                                            \
            std::fprintf(stderr, "%s:%d: internal error: check failed: %s\n", __FILE__, __LINE__, \
                         #cond);                                                                  \
            std::abort();                                                                         \
        }                                                                                         \
    } while (0)
