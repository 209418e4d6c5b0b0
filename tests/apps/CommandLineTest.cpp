// SPDX-License-Identifier: MIT
// The apps' one command-line parser: options in order, values whatever they look like, and the
// same errors in every app.
#include <CommandLine.h>

#include <gtest/gtest.h>

using osgVis::apps::CommandLine;
using osgVis::apps::UsageError;

namespace
{
std::string errorOf(const std::function<void()>& run)
{
    try
    {
        run();
    }
    catch (const UsageError& error)
    {
        return error.what();
    }
    return "(no error)";
}

struct Parsed
{
    bool help = false, show = false;
    std::string mode, model;
    std::vector<std::string> order;
};

CommandLine lineFor(Parsed& parsed)
{
    CommandLine line;
    line.flag({"--help", "-h"}, parsed.help)
        .flag({"--show"}, [&] { parsed.order.push_back("show"); parsed.show = true; })
        .value({"--mode", "-m"}, parsed.mode)
        .value({"--eye"}, [&](const std::string& v) { parsed.order.push_back("eye " + v); })
        .positional([&](const std::string& v) { parsed.model = v; });
    return line;
}
} // namespace

TEST(CommandLine, ReadsFlagsValuesAndPositionalsInOrder)
{
    Parsed parsed;
    lineFor(parsed).parse({"-m", "frustum", "--show", "model.osgb", "--eye", "-1,2,3"});
    EXPECT_FALSE(parsed.help);
    EXPECT_TRUE(parsed.show);
    EXPECT_EQ(parsed.mode, "frustum");
    EXPECT_EQ(parsed.model, "model.osgb");
    // A value is the next argument even when it starts with '-'.
    EXPECT_EQ(parsed.order, (std::vector<std::string>{"show", "eye -1,2,3"}));

    Parsed dash;
    lineFor(dash).parse({"-"});
    EXPECT_EQ(dash.model, "-");
}

TEST(CommandLine, ArgvSkipsTheProgramName)
{
    Parsed parsed;
    char program[] = "app", help[] = "--help";
    char* argv[] = {program, help};
    lineFor(parsed).parse(2, argv);
    EXPECT_TRUE(parsed.help);
    lineFor(parsed).parse(1, argv, 5); // nothing after the first argument: nothing read
}

TEST(CommandLine, ErrorsNameTheArgument)
{
    Parsed parsed;
    const CommandLine line = lineFor(parsed);
    EXPECT_EQ(errorOf([&] { line.parse({"--frobnicate"}); }), "unknown option '--frobnicate' (see --help)");
    EXPECT_EQ(errorOf([&] { line.parse({"--mode"}); }), "--mode expects a value");
    CommandLine noPositional;
    EXPECT_EQ(errorOf([&] { noPositional.parse({"stray"}); }), "unexpected argument 'stray' (see --help)");
    EXPECT_TRUE(line.knows("-h"));
    EXPECT_FALSE(line.knows("--frobnicate"));
}

TEST(CommandLine, OnePositionalIsRefusedTwiceInTheAppsWords)
{
    std::string model;
    CommandLine line;
    line.positional(model, "more than one model given:");
    line.parse({"a.osgb"});
    EXPECT_EQ(model, "a.osgb");
    EXPECT_EQ(errorOf([&] { line.parse({"b.osgb"}); }), "more than one model given: 'a.osgb' and 'b.osgb'");
}

TEST(CommandLine, ReadCommandLineSaysAUsageErrorOrTheHelp)
{
    const auto read = [](const std::function<bool()>& parse, std::string& out, std::string& err)
    {
        testing::internal::CaptureStdout();
        testing::internal::CaptureStderr();
        const std::optional<int> status = osgVis::apps::readCommandLine(parse, "app", "(app --help)\n", "usage\n");
        out = testing::internal::GetCapturedStdout();
        err = testing::internal::GetCapturedStderr();
        return status;
    };
    std::string out, err;
    EXPECT_EQ(read([]() -> bool { throw UsageError("--mode expects a value"); }, out, err), 2);
    EXPECT_EQ(err, "app: --mode expects a value\n(app --help)\n");
    EXPECT_EQ(out, "");
    EXPECT_EQ(read([] { return true; }, out, err), 0);
    EXPECT_EQ(out, "usage\n");
    EXPECT_EQ(err, "");
    EXPECT_EQ(read([] { return false; }, out, err), std::nullopt);
    EXPECT_EQ(out + err, "");
}

TEST(CommandLine, UnsignedIsDigitsWithinItsRange)
{
    using osgVis::apps::parseUnsigned;
    EXPECT_EQ(parseUnsigned("--n", "0"), 0u);
    EXPECT_EQ(parseUnsigned("--n", "18446744073"), 18446744073u);
    for (const char* bad : {"", "-1", " 7", "12abc", "0x2", "1e3", "99999999999999999999"})
        EXPECT_EQ(errorOf([&] { parseUnsigned("--n", bad); }),
                  std::string("--n expects a non-negative integer, got '") + bad + "'");
    EXPECT_EQ(errorOf([&] { parseUnsigned("--n", "9", 1, 8); }), "--n must lie between 1 and 8, got '9'");
    EXPECT_EQ(osgVis::apps::parseUnsignedList("--speeds", "1,2,4", 1, 16), (std::vector<unsigned>{1, 2, 4}));
    EXPECT_EQ(errorOf([&] { osgVis::apps::parseUnsignedList("--speeds", "1,,4", 1, 16); }),
              "--speeds expects a non-negative integer, got ''");
    EXPECT_EQ(errorOf([&] { osgVis::apps::parseUnsignedList("--speeds", "", 1, 16); }), "--speeds is empty");
}

TEST(CommandLine, NumbersAreFiniteDecimals)
{
    using osgVis::apps::parseNumber;
    EXPECT_DOUBLE_EQ(parseNumber("--r", "-2.5e1"), -25.0);
    for (const char* bad : {"", "inf", "nan", "0x10", "1.5m", "1e999"})
        EXPECT_EQ(errorOf([&] { parseNumber("--r", bad); }), std::string("--r expects a number, got '") + bad + "'");
    EXPECT_EQ(errorOf([&] { parseNumber("--r", "0", 0.5, 2.0); }), "--r must lie between 0.5 and 2, got '0'");
}

TEST(CommandLine, SizesTriplesAndLists)
{
    unsigned width = 0, height = 0;
    osgVis::apps::parseSize("--size", "640x480", width, height);
    EXPECT_EQ(width, 640u);
    EXPECT_EQ(height, 480u);
    EXPECT_EQ(errorOf([&] { osgVis::apps::parseSize("--size", "640", width, height); }),
              "--size expects WxH (e.g. 1024x768), got '640'");
    EXPECT_EQ(errorOf([&] { osgVis::apps::parseSize("--size", "0x480", width, height); }),
              "--size must lie between 1x1 and 16384x16384, got '0x480'");

    EXPECT_EQ(osgVis::apps::parseTriple("--eye", "1,-2,3.5"), (std::array<double, 3>{1, -2, 3.5}));
    for (const char* bad : {"1,2", "1,2,3,4", "1,x,3", "1,2,inf"})
        EXPECT_EQ(errorOf([&] { osgVis::apps::parseTriple("--eye", bad); }),
                  std::string("--eye expects x,y,z (three numbers), got '") + bad + "'");

    EXPECT_EQ(osgVis::apps::splitList("a,,b,"), (std::vector<std::string>{"a", "", "b", ""}));
}

TEST(CommandLine, QuotesWhatAShellWouldSplit)
{
    char a[] = "osgvisbench", b[] = "--scene", c[] = "my model.osgb", d[] = "it's";
    char* argv[] = {a, b, c, d};
    EXPECT_EQ(osgVis::apps::quotedCommandLine(4, argv), "osgvisbench --scene 'my model.osgb' 'it'\\''s'");
}
