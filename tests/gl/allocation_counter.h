// Counts the C++ heap allocations alive in this process: every operator new not yet matched by
// an operator delete. Linked only into the long-run test, whose replacement operators feed it.
// The driver allocates with malloc, not new, so this counts this project's allocations (and the
// standard library's on its behalf), exactly and independently of the allocator's slack.
#pragma once

namespace reflect::testing {

long liveCppAllocations();

}  // namespace reflect::testing
