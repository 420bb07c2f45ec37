#include "gui/StatusLine.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace dropscope::gui {
namespace {

TEST(StatusLine, AnAttemptThatRunsThroughKeepsWhatItSaid) {
    StatusLine status;
    status.refuse("an old refusal");
    EXPECT_TRUE(status.attempt("not saved", [&] { status.say("saved a.json"); }));
    EXPECT_EQ(status.text(), "saved a.json");
    EXPECT_FALSE(status.error());
}

TEST(StatusLine, AnAttemptThatThrowsIsRefusedWithTheReason) {
    StatusLine status;
    EXPECT_FALSE(status.attempt("droplet not placed", [] { throw std::runtime_error("it would overlap shape 3"); }));
    EXPECT_EQ(status.text(), "droplet not placed: it would overlap shape 3");
    EXPECT_TRUE(status.error());
}

}  // namespace
}  // namespace dropscope::gui
