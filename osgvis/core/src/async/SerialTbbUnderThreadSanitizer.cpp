// SPDX-License-Identifier: MIT
// ThreadSanitizer builds only (OSGVIS_TSAN): Debian's libtbb is not instrumented, so TSan cannot see
// the happens-before edges of TBB's scheduler (task hand-over, small-object pool reuse) and reports
// every parallel_for body as a race. A TSan build therefore runs TBB loops on the calling thread;
// the threads TSan then checks are ours (AsyncVisibility's worker) and OSG's (cull/draw threads).
// The parallel traversal's own safety is covered by the determinism tests (same answer at every
// thread count) and the AddressSanitizer build.
#if defined(__SANITIZE_THREAD__)
#include <tbb/global_control.h>

namespace
{
const tbb::global_control serialTbbUnderThreadSanitizer(tbb::global_control::max_allowed_parallelism, 1);
}
#endif
