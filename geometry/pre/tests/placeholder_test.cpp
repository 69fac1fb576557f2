#include <gtest/gtest.h>
TEST(PrePlaceholder, Builds) { SUCCEED(); }
