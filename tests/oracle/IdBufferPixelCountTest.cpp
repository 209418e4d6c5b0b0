// SPDX-License-Identifier: MIT
// Per-object pixel counts of the ID-buffer oracle (Result::pixels, the bench's mis-drawn pixels):
// exact counts where the layout leaves no pixel centre on an edge, so the rasterization rule
// decides nothing.

#include "OracleTestScenes.h"

#include <osgVis/oracle/IdBufferOracle.h>

#include <gtest/gtest.h>

#include <map>
#include <string>

using namespace oracletest;
using osgVis::oracle::IdBufferOracle;
using osgVis::oracle::OracleSettings;

namespace
{
// Not square, so a swapped width and height would show.
constexpr unsigned Width = 96, Height = 64;
constexpr std::uint32_t FramePixels = Width * Height;

OracleSettings displaySettings()
{
    OracleSettings settings;
    settings.width = Width;
    settings.height = Height;
    settings.supersample = 2; // the extra render must not add to the display counts
    return settings;
}

// Eye at (0, 0, 10) looking down -z; the view is x in [-3, 3], y in [-2, 2]: 16 pixels per unit both ways,
// so x = 0 is the boundary between pixel columns 47 and 48.
Camera orthoCamera()
{
    Camera camera = lookDownZ(10, 40, 1, 100);
    camera.projection = osg::Matrixd::ortho(-3, 3, -2, 2, 1, 100);
    return camera;
}

// Drawable name → its pixels in the display image, for every visible object.
std::map<std::string, std::uint32_t> pixelsByName(IdBufferOracle& oracle, const Camera& camera)
{
    const IdBufferOracle::Result result = oracle.visible(camera.view, camera.projection);
    EXPECT_EQ(result.pixels.size(), result.visible.size()) << "pixels run parallel to visible";
    std::map<std::string, std::uint32_t> pixels;
    for (std::size_t i = 0; i < result.visible.size() && i < result.pixels.size(); ++i)
        pixels[oracle.objects().at(result.visible[i]).drawable->getName()] = result.pixels[i];
    return pixels;
}

osg::ref_ptr<osg::Group> group(std::initializer_list<osg::Node*> children)
{
    osg::ref_ptr<osg::Group> g = new osg::Group;
    for (osg::Node* child : children)
        g->addChild(child);
    return g;
}

using Counts = std::map<std::string, std::uint32_t>;
} // namespace

TEST(IdBufferPixelCount, QuadFillingTheViewportCountsEveryPixel)
{
    osg::ref_ptr<osg::Group> root = group({inGeode(makeQuadZ(-4, 4, -3, 3, 0, true, "floor"))});
    IdBufferOracle oracle(root.get(), displaySettings());
    EXPECT_EQ(pixelsByName(oracle, orthoCamera()), (Counts{{"floor", FramePixels}}));

    // Under a perspective projection too: a quad far wider than the frustum at its depth.
    const Camera perspective = lookDownZ(10, 40, 1, 100);
    osg::ref_ptr<osg::Group> wide = group({inGeode(makeQuadZ(-50, 50, -50, 50, 0, true, "floor"))});
    IdBufferOracle wideOracle(wide.get(), displaySettings());
    EXPECT_EQ(pixelsByName(wideOracle, perspective), (Counts{{"floor", FramePixels}}));
}

TEST(IdBufferPixelCount, TwoQuadsSplittingTheFrameCountHalfEach)
{
    osg::ref_ptr<osg::Group> root = group({
        inGeode(makeQuadZ(-4, 0, -3, 3, 0, true, "left")),
        inGeode(makeQuadZ(0, 4, -3, 3, 0, true, "right")),
    });
    IdBufferOracle oracle(root.get(), displaySettings());
    EXPECT_EQ(pixelsByName(oracle, orthoCamera()), (Counts{{"left", FramePixels / 2}, {"right", FramePixels / 2}}));
}

// Pixels are those the object shows in the final image, not the fragments it rasterized: a quad over
// the left half in front of one filling the frame leaves the back one the right half.
TEST(IdBufferPixelCount, NearerQuadTakesItsPixelsFromTheOneBehind)
{
    osg::ref_ptr<osg::Group> root = group({
        inGeode(makeQuadZ(-4, 4, -3, 3, 0, true, "back")),
        inGeode(makeQuadZ(-4, 0, -3, 3, 2, true, "front")),
    });
    IdBufferOracle oracle(root.get(), displaySettings());
    EXPECT_EQ(pixelsByName(oracle, orthoCamera()), (Counts{{"back", FramePixels / 2}, {"front", FramePixels / 2}}));
}
