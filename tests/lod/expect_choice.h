#pragma once
// The one check the LOD choice tests share: a choice's primary, partner and partner fade.
#include <gtest/gtest.h>

#include "lod/ladder.h"

namespace sylva::testing {

inline void expect_choice(const ladder_choice& got, representation primary, representation partner, float fade) {
    EXPECT_EQ(got.primary, primary);
    EXPECT_EQ(got.partner, partner);
    EXPECT_NEAR(got.partner_fade, fade, 1e-4f);
}

}  // namespace sylva::testing
