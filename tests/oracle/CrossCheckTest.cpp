// SPDX-License-Identifier: MIT
// The two judges against each other: the ID-buffer render (GL rasterisation of the real graph) and
// the CPU ray caster (Möller–Trumbore at pixel centres) on random boxes from random views.
//
// GL samples coverage at pixel centres too, so at equal resolution the two differ only where a
// triangle edge passes within rounding distance of a sample, or two surfaces are within depth-buffer
// precision of each other: objects whose visible area is a sliver of about one sample. Such a
// disagreement flips between resolutions, so the bound checked is: whatever one judge sees at a
// resolution, the other sees at that resolution or at twice it (with at most one exception per
// view, printed), and the exact-equality rate is printed.

#include "OracleTestScenes.h"

#include <osgVis/oracle/Oracle.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <iterator>
#include <random>

using namespace oracletest;
using namespace osgVis::oracle;

namespace
{
using Set = std::vector<std::uint32_t>;

Set minus(const Set& a, const Set& b)
{
    Set out;
    std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
    return out;
}

Set unite(const Set& a, const Set& b)
{
    Set out;
    std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
    return out;
}

osg::ref_ptr<osg::Group> randomBoxes(unsigned count, std::uint32_t seed)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> position(-10.0f, 10.0f), size(0.2f, 2.0f);
    osg::ref_ptr<osg::Group> root = new osg::Group;
    for (unsigned i = 0; i < count; ++i)
    {
        const osg::Vec3 centre(position(random), position(random), position(random));
        const osg::Vec3 half(size(random), size(random), size(random));
        root->addChild(inGeode(makeBox(centre, half, "box" + std::to_string(i))));
    }
    return root;
}

std::vector<Camera> randomViews(unsigned count, std::uint32_t seed)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::vector<Camera> views;
    while (views.size() < count)
    {
        osg::Vec3d eye(unit(random), unit(random), unit(random));
        if (eye.length2() < 0.05 || eye.length2() > 1.0)
            continue;
        eye.normalize();
        eye *= 22.0;
        const osg::Vec3d centre(3 * unit(random), 3 * unit(random), 3 * unit(random));
        Camera camera;
        camera.view = osg::Matrixd::lookAt(eye, centre, std::abs(eye.z()) > 20 ? osg::Vec3d(0, 1, 0) : osg::Vec3d(0, 0, 1));
        switch (views.size() % 3)
        {
        case 0: camera.projection = osg::Matrixd::perspective(50.0, 1.0, 1.0, 60.0); break;
        case 1: camera.projection = osg::Matrixd::frustum(-0.2, 0.6, -0.5, 0.3, 1.0, 60.0); break;
        default: camera.projection = osg::Matrixd::ortho(-12, 12, -12, 12, 1, 60); break;
        }
        views.push_back(camera);
    }
    return views;
}
} // namespace

TEST(OracleCrossCheck, IdBufferAgreesWithRayCastingOnRandomBoxes)
{
    constexpr unsigned Size = 256, Views = 15;
    osg::ref_ptr<osg::Group> root = randomBoxes(50, 7);
    OracleSettings settings;
    settings.width = settings.height = Size;
    settings.supersample = 1;
    IdBufferOracle display(root.get(), settings);
    settings.width = settings.height = 2 * Size;
    IdBufferOracle doubled(root.get(), settings);
    settings.width = settings.height = Size;
    settings.supersample = 2;
    IdBufferOracle withSupersample(root.get(), settings);
    const RayCaster rayCaster(display.objects());

    std::size_t visibleTotal = 0, equalViews = 0, mismatches = 0, mismatchesDoubled = 0, supersampleExtras = 0;
    for (const Camera& camera : randomViews(Views, 11))
    {
        const Set idSet = display.visible(camera.view, camera.projection).visible;
        const Set idSetDoubled = doubled.visible(camera.view, camera.projection).visible;
        const IdBufferOracle::Result idUnion = withSupersample.visible(camera.view, camera.projection);
        const Set raySet = rayCaster.visible(camera.view, camera.projection, Size, Size);
        const Set raySetDoubled = rayCaster.visible(camera.view, camera.projection, 2 * Size, 2 * Size);

        visibleTotal += idSet.size();
        equalViews += idSet == raySet;
        mismatches += minus(idSet, raySet).size() + minus(raySet, idSet).size();
        mismatchesDoubled += minus(idSetDoubled, raySetDoubled).size() + minus(raySetDoubled, idSetDoubled).size();
        supersampleExtras += idUnion.onlyInSupersampled;

        // The supersampled oracle is the display render united with the doubled one.
        EXPECT_EQ(idUnion.visible, unite(idSet, idSetDoubled));
        // Every object one judge sees, the other sees at the same or the doubled resolution, but for
        // at most one sliver per view.
        EXPECT_LE(minus(raySet, unite(idSet, idSetDoubled)).size(), 1u);
        EXPECT_LE(minus(idSet, unite(raySet, raySetDoubled)).size(), 1u);
        EXPECT_GT(idSet.size(), 3u) << "views should look at something";
    }
    std::cout << "[ oracle  ] " << Views << " views, " << visibleTotal << " visible objects (" << Size << "²): "
              << equalViews << " views identical, " << mismatches << " objects differ at " << Size << "², "
              << mismatchesDoubled << " at " << 2 * Size << "²; supersampling added " << supersampleExtras
              << " objects" << std::endl;
    EXPECT_LE(mismatches, Views / 2);
}
