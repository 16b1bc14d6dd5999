// The one progress display (core/io/progress_line.h): what it says, and when it says it.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "core/io/progress_line.h"

namespace collide {
namespace {

std::string contents(std::FILE* f) {
    std::fflush(f);
    std::rewind(f);
    std::string text;
    for (int c; (c = std::fgetc(f)) != EOF;) text += char(c);
    return text;
}

TEST(ProgressLine, TimeLeftIsElapsedTimesRemainingOverDone) {
    // A quarter done in 10 s: 30 s left at the same rate.
    EXPECT_EQ(ProgressLine::compose(0.25, "t = 2.5 of 10", 10), "t = 2.5 of 10 (25%), 0:10 elapsed, about 0:30 left");
    // Nothing done yet: no estimate. All done: nothing left to estimate.
    EXPECT_EQ(ProgressLine::compose(0, "x", 3), "x (0%), 0:03 elapsed");
    EXPECT_EQ(ProgressLine::compose(1, "x", 3725), "x (100%), 1:02:05 elapsed");
    // Fractions outside [0, 1] (a solver overshooting its last output time) are clamped.
    EXPECT_EQ(ProgressLine::compose(1.5, "x", 1), "x (100%), 0:01 elapsed");
}

TEST(ProgressLine, DurationsReadAsClockTimes) {
    EXPECT_EQ(ProgressLine::format_duration(0.4), "0:00");
    EXPECT_EQ(ProgressLine::format_duration(65), "1:05");
    EXPECT_EQ(ProgressLine::format_duration(3723), "1:02:03");
    EXPECT_EQ(ProgressLine::format_duration(-5), "0:00");
}

TEST(ProgressLine, ALogStaysQuietForShortWorkButPrintsForcedLines) {
    std::FILE* log = std::tmpfile();
    ASSERT_NE(log, nullptr);
    {
        ProgressLine line(log, ProgressLine::Style{false, 3600, false});
        line.update(0.5, "half");  // inside the interval: nothing
        line.update(1.0, "all", /*force=*/true);
    }
    const std::string text = contents(log);
    EXPECT_EQ(text.find("half"), std::string::npos) << text;
    EXPECT_NE(text.find("all (100%)"), std::string::npos) << text;
    EXPECT_EQ(text.find('\r'), std::string::npos) << "no terminal control characters in a log: " << text;
    std::fclose(log);
}

TEST(ProgressLine, ATerminalLineIsRewrittenInPlaceAndClearedAtTheEnd) {
    std::FILE* tty = std::tmpfile();
    ASSERT_NE(tty, nullptr);
    {
        ProgressLine line(tty, ProgressLine::Style{true, 10, false});
        line.update(0.5, "half", true);
    }  // the destructor clears the line
    const std::string text = contents(tty);
    EXPECT_EQ(text.rfind("\r", 0), 0u) << "starts by returning the cursor: " << text;
    EXPECT_NE(text.find("half (50%)"), std::string::npos);
    EXPECT_EQ(text.substr(text.size() - 4), "\r\033[K") << "ends by erasing the line";
    std::fclose(tty);
}

TEST(ProgressLine, KeepLastLineEndsTheLineInsteadOfErasingIt) {
    std::FILE* tty = std::tmpfile();
    ASSERT_NE(tty, nullptr);
    {
        ProgressLine line(tty, ProgressLine::Style{true, 10, true});
        line.update(1.0, "[4/4]", true);
    }
    const std::string text = contents(tty);
    EXPECT_EQ(text.back(), '\n');
    EXPECT_NE(text.find("[4/4] (100%)"), std::string::npos);
    std::fclose(tty);
}

}  // namespace
}  // namespace collide
