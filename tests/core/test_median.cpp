// The sample median against values worked out by hand.
#include <gtest/gtest.h>

#include "core/numerics/median.h"

namespace collide {
namespace {

TEST(Median, OddCountIsTheMiddleValueWhateverTheOrder) {
    EXPECT_DOUBLE_EQ(median({5.0, 1.0, 3.0}), 3.0);
    EXPECT_DOUBLE_EQ(median({2.0}), 2.0);
}

TEST(Median, EvenCountIsTheMeanOfTheTwoMiddleValues) {
    EXPECT_DOUBLE_EQ(median({4.0, 1.0, 3.0, 10.0}), 3.5);
    EXPECT_DOUBLE_EQ(median({7.0, 7.0}), 7.0);
}

TEST(Median, NoSamplesGiveZero) { EXPECT_DOUBLE_EQ(median({}), 0.0); }

}  // namespace
}  // namespace collide
