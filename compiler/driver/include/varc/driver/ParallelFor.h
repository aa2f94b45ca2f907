// SPDX-License-Identifier: Apache-2.0
// A minimal worker pool: runs an indexed job over [0, count) on N threads.
#pragma once

#include <cstddef>
#include <functional>

namespace varc::driver {

// Calls |job(i)| once for every i in [0, count), using up to |threads| threads (the caller's
// thread included). Jobs are claimed in index order; each job writes only its own result slot,
// so output order never depends on scheduling. With |firstAlone|, job 0 runs to completion
// before any other starts (glslang builds shared symbol tables on its first use). When a job
// throws, no further jobs start, every thread finishes its current job, and the first exception
// is rethrown on the caller's thread (never std::terminate).
void parallelFor(size_t count, unsigned threads, const std::function<void(size_t)>& job,
                 bool firstAlone = false);

// The default thread count: the machine's hardware concurrency, at least 1.
unsigned defaultThreadCount();

}  // namespace varc::driver
