// SPDX-License-Identifier: MIT
// osgvisbench --report: the page for people and its pictures, and that a real browser shows the
// page (Chromium headless takes a screenshot of it).
#include "AppProcess.h"

#include <osgDB/ReadFile>

#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <set>
#include <string>

using namespace osgVis::test;

namespace
{
std::size_t count(const std::string& text, const std::string& what)
{
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
        ++n;
    return n;
}

std::size_t pixelsOf(const osg::Image& image, unsigned char r, unsigned char g, unsigned char b)
{
    std::size_t n = 0;
    for (int y = 0; y < image.t(); ++y)
        for (int x = 0; x < image.s(); ++x)
        {
            const unsigned char* p = image.data(x, y);
            n += p[0] == r && p[1] == g && p[2] == b;
        }
    return n;
}

// The report of a tiny office walk, made in the current test's own folder (ctest runs the tests of
// this file in parallel processes).
const std::filesystem::path& report()
{
    static const std::filesystem::path directory = [] {
        const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
        const std::filesystem::path dir = scratchDirectory("bench", "report-" + test) / "out";
        const AppRun run = runApp(OSGVIS_BENCH_EXE, "--generate office --triangles 5000 --views 8 --size 160x128 "
                                                    "--modes osg,frustum,octree,exact --report '" +
                                                        dir.string() + "' --pictures 2");
        EXPECT_EQ(run.exitCode, 0) << run.output;
        EXPECT_NE(run.output.find("report: " + (dir / "index.html").string()), std::string::npos) << run.output;
        EXPECT_NE(run.output.find("best mode: "), std::string::npos) << run.output;
        return dir;
    }();
    return directory;
}
} // namespace

TEST(BenchReport, PageHoldsTableAndPlotsAndFetchesNothing)
{
    if (!haveDisplay())
        GTEST_SKIP() << "needs an X display (scripts/test.sh provides Xvfb)";
    const std::string html = readText(report() / "index.html");
    ASSERT_FALSE(html.empty());
    EXPECT_EQ(count(html, "<svg"), 2u) << "drawn triangles and cull time per view";
    EXPECT_EQ(count(html, "<polyline"), 2u * 4u) << "one line per mode in each plot";
    EXPECT_NE(html.find("drawn triangles per view"), std::string::npos);
    EXPECT_NE(html.find("0 false-invisible objects in conservative modes"), std::string::npos);
    for (const char* mode : {">osg<", ">frustum<", ">octree<", ">exact<"})
        EXPECT_NE(html.find(mode), std::string::npos) << mode;
    EXPECT_EQ(count(html, "<img src=\"view-"), 2u);
    // Self-contained: no stylesheet, script or image from anywhere but the folder itself.
    EXPECT_FALSE(std::regex_search(html, std::regex(R"((src|href)\s*=\s*"(https?:|//))"))) << "fetches from the network";
    EXPECT_EQ(html.find("<script"), std::string::npos);
}

TEST(BenchReport, PicturesShowTheBaselineAndTheBestModeWithTheSamePixelsAndAMap)
{
    if (!haveDisplay())
        GTEST_SKIP() << "needs an X display (scripts/test.sh provides Xvfb)";
    std::vector<std::filesystem::path> pictures;
    for (const auto& entry : std::filesystem::directory_iterator(report()))
        if (entry.path().filename().string().rfind("view-", 0) == 0)
            pictures.push_back(entry.path());
    ASSERT_EQ(pictures.size(), 2u);
    for (const std::filesystem::path& path : pictures)
    {
        const osg::ref_ptr<osg::Image> image = osgDB::readRefImageFile(path.string());
        ASSERT_TRUE(image.valid()) << path;
        EXPECT_EQ(image->t(), 128);
        ASSERT_GT(image->s(), 160 + 4 + 160 + 4) << "osg | best mode | map";
        // A conservative mode draws exactly what osg draws: the two frames match pixel for pixel.
        std::size_t differing = 0, lit = 0;
        for (int y = 0; y < 128; ++y)
            for (int x = 0; x < 160; ++x)
            {
                const unsigned char *a = image->data(x, y), *b = image->data(x + 164, y);
                differing += a[0] != b[0] || a[1] != b[1] || a[2] != b[2];
                lit += a[0] + a[1] + a[2] > 30;
            }
        EXPECT_EQ(differing, 0u) << path;
        EXPECT_GT(lit, 1000u) << path << ": the frame shows the office, not an empty view";
        EXPECT_GT(pixelsOf(*image, 60, 200, 90), 10u) << path << ": the map shows drawn objects in green";
        EXPECT_GT(pixelsOf(*image, 250, 220, 60), 10u) << path << ": and the frustum in yellow";
    }
}

#ifdef OSGVIS_CHROMIUM
TEST(BenchReport, ChromiumShowsThePage)
{
    if (!haveDisplay())
        GTEST_SKIP() << "needs an X display for the bench run (scripts/test.sh provides Xvfb)";
    const std::filesystem::path shot = scratchDirectory("bench", "report-browser-shot") / "page.png";
    const std::filesystem::path profile = shot.parent_path() / "profile";
    const AppRun run = runApp(OSGVIS_CHROMIUM,
                              "--headless --no-sandbox --disable-gpu --disable-quic --no-first-run "
                              "--disable-background-networking --disable-component-update --disable-sync "
                              "--hide-scrollbars --user-data-dir='" + profile.string() + "' --window-size=1100,1300 "
                              "--screenshot='" + shot.string() + "' 'file://" + (report() / "index.html").string() + "'");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const osg::ref_ptr<osg::Image> page = osgDB::readRefImageFile(shot.string());
    ASSERT_TRUE(page.valid()) << run.output;
    EXPECT_EQ(page->s(), 1100);
    std::set<unsigned> colours;
    for (int y = 0; y < page->t(); y += 2)
        for (int x = 0; x < page->s(); x += 2)
            colours.insert(unsigned(page->data(x, y)[0]) << 16 | unsigned(page->data(x, y)[1]) << 8 | page->data(x, y)[2]);
    EXPECT_GT(colours.size(), 100u) << "a blank or error page has few colours";
    // The page's own colours: the green summary boxes and the table header.
    EXPECT_GT(pixelsOf(*page, 0xee, 0xf6, 0xee), 5000u) << "the summary boxes";
    EXPECT_GT(pixelsOf(*page, 0xf0, 0xf0, 0xf0), 2000u) << "the table's header row";
}
#endif
