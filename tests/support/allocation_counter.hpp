#pragma once
// Counts heap allocations made through the global operator new of the test binary, so
// that tests can assert that a hot path allocates nothing.

namespace crux::testing {

long allocation_count();

}  // namespace crux::testing
