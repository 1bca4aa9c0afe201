#include "GlTest.h"

#include <memory>

namespace photopic::test {

namespace {
std::unique_ptr<HeadlessContext> gContext;
std::string gReason;
} // namespace

HeadlessContext* glContext() {
    return gContext.get();
}
const std::string& glUnavailableReason() {
    return gReason;
}

} // namespace photopic::test

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    // gtest_discover_tests lists tests without running them: no context needed for that.
    if (!::testing::GTEST_FLAG(list_tests)) {
        try {
            photopic::test::gContext = std::make_unique<photopic::HeadlessContext>(
                photopic::HeadlessContextCreateInfo{.debug = true});
        } catch (const std::exception& e) {
            photopic::test::gReason = e.what();
        }
    }
    const int result = RUN_ALL_TESTS();
    photopic::test::gContext.reset();
    return result;
}
