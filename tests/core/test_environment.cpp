// core/Environment.h: what "set" means for Photopic's environment variables.

#include "core/Environment.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace photopic {
namespace {

constexpr const char* kName = "PHOTOPIC_TEST_ENVIRONMENT";

struct Unset {
    ~Unset() { unsetenv(kName); }
};

TEST(Environment, AnEmptyValueIsUnset) {
    const Unset unset;
    unsetenv(kName);
    EXPECT_FALSE(environmentValue(kName).has_value());
    EXPECT_FALSE(environmentSwitch(kName));
    setenv(kName, "", 1);
    EXPECT_FALSE(environmentValue(kName).has_value());
    EXPECT_FALSE(environmentSwitch(kName));
}

TEST(Environment, ASwitchIsOnForAnythingButZero) {
    const Unset unset;
    setenv(kName, "0", 1);
    EXPECT_EQ(environmentValue(kName), "0");
    EXPECT_FALSE(environmentSwitch(kName));
    for (const char* on : {"1", "yes", "tiles"}) {
        setenv(kName, on, 1);
        EXPECT_EQ(environmentValue(kName), on);
        EXPECT_TRUE(environmentSwitch(kName)) << on;
    }
}

} // namespace
} // namespace photopic
