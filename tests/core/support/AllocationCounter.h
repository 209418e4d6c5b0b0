// SPDX-License-Identifier: MIT
#pragma once
// Counts every global operator new in the test executable that links AllocationCounter.cpp, so
// tests can show that a query phase allocates nothing.
#include <cstddef>

namespace osgVis::test
{
std::size_t allocationCount();
} // namespace osgVis::test
