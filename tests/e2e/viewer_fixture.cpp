// The one X server of the end-to-end tests (viewer_fixture.h).

#include "viewer_fixture.h"

namespace meshedit::test::e2e {
namespace {

[[maybe_unused]] ::testing::Environment* const g_x_environment =
    ::testing::AddGlobalTestEnvironment(new XEnvironment);

}  // namespace
}  // namespace meshedit::test::e2e
