#pragma once
// Shared by the stress tests: every row a check returns must pass; on failure the row says
// what was measured against which limit.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "app/stress/stress_checks.h"

namespace sylva::testing {

inline void expect_all_pass(const std::vector<stress_row>& rows) {
    ASSERT_FALSE(rows.empty());
    for (const stress_row& r : rows)
        EXPECT_TRUE(r.passed) << r.check << ": measured " << r.measured << ", limit " << r.limit
                              << (r.detail.empty() ? "" : "; ") << r.detail;
}

// The row whose check text starts with `prefix` (fails the test when there is none).
inline const stress_row& row_named(const std::vector<stress_row>& rows, const std::string& prefix) {
    for (const stress_row& r : rows)
        if (r.check.rfind(prefix, 0) == 0) return r;
    ADD_FAILURE() << "no row starting with " << prefix;
    static const stress_row none;
    return none;
}

}  // namespace sylva::testing
