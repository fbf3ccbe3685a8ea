#include <gtest/gtest.h>

#include "mink/geometry/orientation.hpp"

TEST(Orientation, Placeholder) { EXPECT_EQ(mink::orient2d({0, 0}, {1, 0}, {0, 1}), 1); }
