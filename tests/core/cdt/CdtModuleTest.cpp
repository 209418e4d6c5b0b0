// SPDX-License-Identifier: MIT
// The CDT method (Luka) against the ray-cast reference: every object a ray sees is kept, in every
// rule ("cdt", "cdt-depthfree", "cdt-depth"), on a city walk, views from inside geometry, grazing,
// up and down, wide, narrow, off-centre and orthographic projections, far from the origin; and it
// culls what stands behind a street front, fusing the faces of a building and neighbouring walls.
#include "BoxScenes.h"
#include "RayCastVisibility.h"
#include "RegionSampling.h"

#include <osgVis/core/api/ModuleRegistry.h>
#include <osgVis/core/cdt/CdtModule.h>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

using namespace osgVis::core;
using namespace osgVis::test;

namespace
{
const char* const Modes[] = {"cdt", "cdt-depthfree", "cdt-depth"};

VisibleSet cullAll(VisibilityModule& module, const Scene& scene, const View& view)
{
    VisibleSet visible(scene.objects.size(), true);
    module.cull(view, visible);
    return visible;
}

/// Objects the rays see that the answer lacks, one line each.
std::string missed(const Scene& scene, const RayCastResult& seen, const VisibleSet& answer)
{
    std::string out;
    for (ObjectId id = 0; id < scene.objects.size(); ++id)
        if (seen.visible[id] && !answer.test(id))
            out += "  " + scene.objects[id].name + " (seen at pixel " + std::to_string(seen.seenAt[id].x) + ", " +
                   std::to_string(seen.seenAt[id].y) + ")\n";
    return out;
}

struct Tally
{
    std::size_t frames = 0, failed = 0, hiddenInFrustum = 0, culledHidden = 0;
    double efficacy() const { return hiddenInFrustum ? double(culledHidden) / double(hiddenInFrustum) : 0.0; }
};

void checkViews(const std::string& what, const Scene& scene, const std::vector<View>& views, Tally* tallies = nullptr)
{
    const RayCastVisibility rays(scene);
    std::vector<RayCastResult> seen;
    for (const View& view : views)
        seen.push_back(rays.cast(view));
    int modeIndex = 0;
    for (const char* mode : Modes)
    {
        const std::unique_ptr<VisibilityModule> module = createModule(mode);
        module->setScene(scene);
        Tally tally;
        for (std::size_t f = 0; f < views.size(); ++f)
        {
            const VisibleSet answer = cullAll(*module, scene, views[f]);
            const std::string lost = missed(scene, seen[f], answer);
            ++tally.frames;
            if (!lost.empty() && tally.failed++ == 0)
                ADD_FAILURE() << what << ", " << mode << ", view " << f << ": culled what the rays see:\n" << lost;
            for (ObjectId id = 0; id < scene.objects.size(); ++id)
                if (!seen[f].visible[id] && views[f].frustum.classify(scene.objects[id].bounds) != Containment::Outside)
                {
                    ++tally.hiddenInFrustum;
                    tally.culledHidden += !answer.test(id);
                }
        }
        EXPECT_EQ(tally.failed, 0u) << what << ", " << mode;
        std::printf("[ %-13s ] %s: %zu views, occlusion efficacy %.3f (%zu of %zu hidden object-views culled)\n", mode,
                    what.c_str(), tally.frames, tally.efficacy(), tally.culledHidden, tally.hiddenInFrustum);
        if (tallies)
            tallies[modeIndex] = tally;
        ++modeIndex;
    }
}

Vec3 direction(double yawDegrees, double pitchDegrees)
{
    const double yaw = glm::radians(yawDegrees), pitch = glm::radians(pitchDegrees);
    return {std::cos(pitch) * std::sin(yaw), std::cos(pitch) * std::cos(yaw), std::sin(pitch)};
}

Vec3 upFor(const Vec3& d) { return std::abs(d.z) > 0.99 ? Vec3(0, 1, 0) : Vec3(0, 0, 1); }
} // namespace

TEST(CdtModule, RegisteredUnderItsThreeNames)
{
    for (const char* mode : Modes)
    {
        ASSERT_TRUE(hasModule(mode)) << mode;
        const std::unique_ptr<VisibilityModule> module = createModule(mode);
        EXPECT_STREQ(module->name(), mode);
        EXPECT_FALSE(module->approximate());
        EXPECT_FALSE(module->supportsRegions());
    }
}

TEST(CdtModule, CityWalkKeepsEverythingTheRaysSeeAndCullsBehindTheStreetFront)
{
    const City city = makeCity();
    std::vector<View> views;
    for (int i = 0; i < 30; ++i)
    {
        const double t = i * 0.8;
        views.push_back(lookFrom({85.0 + 0.5 * std::sin(0.3 * t), -8.0 + 6.0 * t, 1.7},
                                 direction(20.0 * std::sin(0.6 * t), -1.0), {0, 0, 1}, 60.0, 160, 120));
    }
    Tally tallies[3];
    checkViews("city street walk", city.scene, views, tallies);
    for (const Tally& t : tallies)
        EXPECT_GT(t.efficacy(), 0.3) << "the street front hides most of the city";
}

TEST(CdtModule, GazeInEveryDirectionFromJitteredEyes)
{
    const City city = makeCity();
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<View> views;
    for (int i = 0; i < 24; ++i)
    {
        // Street crossings and kerbs, some eyes inside buildings; gaze up, down, grazing.
        const Vec3 eye(-5.0 + 30.0 * std::floor(unit(random) * 6.0) + 4.0 * (unit(random) - 0.5),
                       -5.0 + 180.0 * unit(random), 0.2 + 12.0 * unit(random) * unit(random));
        const double pitch = i % 6 == 0 ? 89.0 : (i % 6 == 1 ? -89.0 : (i % 6 == 2 ? 0.0 : 60.0 * (unit(random) - 0.5)));
        const Vec3 d = direction(360.0 * unit(random), pitch);
        const double fovy = i % 4 == 0 ? 110.0 : (i % 4 == 1 ? 12.0 : 60.0);
        views.push_back(lookFrom(eye, d, upFor(d), fovy, 128, 96));
    }
    checkViews("jittered eyes, every gaze, wide and narrow", city.scene, views);
}

TEST(CdtModule, OffCentreAndOrthographicProjections)
{
    const City city = makeCity();
    std::vector<View> views;
    for (int i = 0; i < 8; ++i)
    {
        View v = lookFrom({85.0, -8.0 + 15.0 * i, 1.7}, direction(10.0 * i, 0.0), {0, 0, 1}, 60.0, 128, 96);
        const Mat4 projection = i % 2 ? glm::frustum(-0.02, 0.11, -0.03, 0.05, 0.1, 500.0)
                                      : glm::ortho(-40.0, 40.0, -30.0, 30.0, 0.1, 500.0);
        views.push_back(makeView(v.viewMatrix, projection, 0.0, 128, 96));
    }
    checkViews("off-centre and orthographic", city.scene, views);
}

TEST(CdtModule, FarFromTheOrigin)
{
    // The city moved 10^6 m away, viewed from its streets.
    City city = makeCity();
    const Vec3 shift(1.0e6, -1.0e6, 0.0);
    Scene moved;
    for (const SceneObject& object : city.scene.objects)
    {
        std::vector<Triangle> tris;
        const auto [first, end] = city.scene.trianglesOf(object);
        for (std::size_t t = first; t < end; ++t)
        {
            Triangle tri = city.scene.triangles[t];
            tri.a += Vec3f(shift), tri.b += Vec3f(shift), tri.c += Vec3f(shift);
            tris.push_back(tri);
        }
        addTriangles(moved, tris, object.name, object.flags);
    }
    std::vector<View> views;
    for (int i = 0; i < 10; ++i)
        views.push_back(lookFrom(shift + Vec3(85.0, -8.0 + 15.0 * i, 1.7), direction(15.0 * i, 0.0), {0, 0, 1}, 60.0, 128, 96));
    checkViews("10^6 m from the origin", moved, views);
}

TEST(CdtModule, WallOfSeparateObjectsFusesAlongSharedEdges)
{
    // A wall of four 5 m quads, each its own object, sharing edges exactly; a box behind the seam
    // between two of them is hidden only if they fuse.
    Scene scene;
    for (int i = 0; i < 4; ++i)
    {
        const Vec3f a(-10.0f + 5.0f * i, 10.0f, 0.0f), b(-5.0f + 5.0f * i, 10.0f, 0.0f);
        const Vec3f c(b.x, 10.0f, 6.0f), d(a.x, 10.0f, 6.0f);
        addTriangles(scene, {{a, b, c}, {a, c, d}}, "panel " + std::to_string(i));
    }
    const ObjectId target = addBox(scene, {-1.0, 20.0, 1.0}, {1.0, 21.0, 3.0}, "target behind the seam");
    const View view = lookFrom({0.0, 0.0, 2.0}, {0, 1, 0}, {0, 0, 1}, 40.0, 160, 120);
    const RayCastVisibility rays(scene);
    ASSERT_FALSE(rays.cast(view).visible[target]);
    for (const char* mode : {"cdt", "cdt-depth"})
    {
        const std::unique_ptr<VisibilityModule> module = createModule(mode);
        module->setScene(scene);
        const VisibleSet answer = cullAll(*module, scene, view);
        const CdtModule::Statistics st = dynamic_cast<CdtModule&>(*module).lastStatistics();
        EXPECT_FALSE(answer.test(target)) << mode << ": the panels did not fuse (" << st.occludersDrawn
                                          << " occluders drawn, " << st.sharedEdgesKept << " shared edges kept)";
    }
}

TEST(CdtModule, KeepsWhatIsSeenThroughAOnePixelSlit)
{
    // Two panels 4 cm apart: at 10 m that is about a pixel; the box behind is seen through it.
    Scene scene;
    addBox(scene, {-10.0, 10.0, 0.0}, {-0.02, 10.5, 6.0}, "left panel");
    addBox(scene, {0.02, 10.0, 0.0}, {10.0, 10.5, 6.0}, "right panel");
    const ObjectId target = addBox(scene, {-1.0, 20.0, 1.0}, {1.0, 21.0, 3.0}, "target behind the slit");
    const View view = lookFrom({0.0, 0.0, 2.0}, {0, 1, 0}, {0, 0, 1}, 40.0, 160, 120);
    const RayCastVisibility rays(scene);
    RayCastOptions dense;
    dense.samplesPerAxis = 8;
    ASSERT_TRUE(rays.cast(view, dense).visible[target]);
    for (const char* mode : Modes)
    {
        const std::unique_ptr<VisibilityModule> module = createModule(mode);
        module->setScene(scene);
        EXPECT_TRUE(cullAll(*module, scene, view).test(target)) << mode;
    }
}

TEST(CdtModule, TJunctionSeamIsNotTrustedAsWatertight)
{
    // A tall panel beside two short ones stacked on top of each other: the short panels' shared
    // corner lies on the tall panel's edge (a T-junction). No shared edge, so the seam is eroded:
    // a box seen only along the seam stays visible, one behind the tall panel alone is culled.
    Scene scene;
    addBox(scene, {-5.0, 10.0, 0.0}, {0.0, 10.5, 6.0}, "tall panel");
    addBox(scene, {0.0, 10.0, 0.0}, {5.0, 10.5, 3.0}, "lower short panel");
    addBox(scene, {0.0, 10.0, 3.0}, {5.0, 10.5, 6.0}, "upper short panel");
    const ObjectId seam = addBox(scene, {-0.5, 20.0, 1.0}, {0.5, 21.0, 2.0}, "behind the seam");
    const ObjectId solid = addBox(scene, {-3.5, 20.0, 1.0}, {-2.5, 21.0, 2.0}, "behind the tall panel");
    const View view = lookFrom({0.0, 0.0, 2.0}, {0, 1, 0}, {0, 0, 1}, 40.0, 160, 120);
    for (const char* mode : Modes)
    {
        const std::unique_ptr<VisibilityModule> module = createModule(mode);
        module->setScene(scene);
        const VisibleSet answer = cullAll(*module, scene, view);
        EXPECT_TRUE(answer.test(seam)) << mode << ": fused across a T-junction the GPU may crack";
        const CdtModule::Statistics st = dynamic_cast<CdtModule&>(*module).lastStatistics();
        EXPECT_FALSE(answer.test(solid)) << mode << ": " << st.occludersDrawn << " occluders drawn, " << st.sharedEdgesKept
                                         << " shared edges kept, " << st.nodesVisited << " nodes visited";
    }
}

TEST(CdtModule, TestBudgetKeepsTheRestVisible)
{
    const City city = makeCity();
    const View view = lookFrom({85.0, -8.0, 1.7}, {0, 1, 0}, {0, 0, 1}, 60.0, 160, 120);
    CdtOptions options;
    options.testBudget = 5;
    CdtModule module(options);
    module.setScene(city.scene);
    const VisibleSet answer = cullAll(module, city.scene, view);
    const CdtModule::Statistics stats = module.lastStatistics();
    EXPECT_TRUE(stats.testBudgetReached);
    EXPECT_LE(stats.nodesVisited + stats.objectsTested, 5u);
    EXPECT_GT(answer.count(), city.scene.objects.size() / 2);
}
