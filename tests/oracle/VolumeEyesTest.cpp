// SPDX-License-Identifier: MIT
// The eyes standing for a box of viewpoints, and the six cube faces that see all around each.
#include <osgVis/oracle/CubeFaceViews.h>
#include <osgVis/oracle/VolumeEyes.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

using osgVis::oracle::volumeEyes;

TEST(VolumeEyes, CornersFaceCentresThenSeededInteriorPoints)
{
    const osg::BoundingBoxd box(-1, 2, 0, 3, 4, 0.5);
    const std::vector<osg::Vec3d> eyes = volumeEyes(box, 50, 7);
    ASSERT_EQ(eyes.size(), 8u + 6u + 50u);
    for (unsigned c = 0; c < 8; ++c)
        EXPECT_EQ(eyes[c], box.corner(c));
    EXPECT_EQ(eyes[8], osg::Vec3d(-1, 3, 0.25)); // the -x face's centre first
    EXPECT_EQ(eyes[13], osg::Vec3d(1, 3, 0.5));  // the +z face's last
    for (std::size_t i = 14; i < eyes.size(); ++i)
    {
        EXPECT_TRUE(box.contains(eyes[i])) << i;
        EXPECT_NE(eyes[i].x(), box.xMin());
    }
    EXPECT_EQ(volumeEyes(box, 50, 7), eyes);
    EXPECT_NE(volumeEyes(box, 50, 8)[20], eyes[20]);
    // A point box is one eye however many are asked for; a flat one has 4 corners and 5 face centres.
    EXPECT_EQ(volumeEyes(osg::BoundingBoxd(1, 1, 1, 1, 1, 1), 48, 1).size(), 1u);
    EXPECT_EQ(volumeEyes(osg::BoundingBoxd(0, 0, 0, 1, 1, 0), 0, 1).size(), 4u + 5u);
    EXPECT_THROW(volumeEyes(osg::BoundingBoxd(), 4, 1), std::invalid_argument);
}

TEST(CubeFaceViews, EveryDirectionFallsInOneFace)
{
    const osg::Vec3d eye(3, -2, 1);
    const auto views = osgVis::oracle::cubeFaceViews(eye);
    const osg::Matrixd projection = osgVis::oracle::cubeFaceProjection(0.01, 100.0);
    std::mt19937 random(3);
    std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
    for (int i = 0; i < 2000; ++i)
    {
        osg::Vec3d direction(coordinate(random), coordinate(random), coordinate(random));
        if (direction.normalize() < 1e-3)
            continue;
        int faces = 0;
        for (const osg::Matrixd& view : views)
        {
            const osg::Vec4d clip = osg::Vec4d(eye + direction * 5.0, 1.0) * view * projection;
            if (clip.w() > 0 && std::abs(clip.x()) <= clip.w() && std::abs(clip.y()) <= clip.w())
                ++faces;
        }
        EXPECT_EQ(faces, 1) << direction.x() << "," << direction.y() << "," << direction.z();
    }
    // Each face looks along its axis: its centre is straight ahead.
    const osg::Vec4d ahead = osg::Vec4d(eye + osg::Vec3d(0, 0, -1), 1.0) * views[5] * projection;
    EXPECT_NEAR(ahead.x() / ahead.w(), 0.0, 1e-12);
    EXPECT_NEAR(ahead.y() / ahead.w(), 0.0, 1e-12);
}
