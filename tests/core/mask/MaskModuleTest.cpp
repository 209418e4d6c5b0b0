// SPDX-License-Identifier: MIT
// Contract tests of the mask module (issue 5) against the ray-cast reference (RayCastVisibility,
// no shared code): a street walk through a small city, eyes on the boundary of the δ-ball with
// targets barely hidden at the frame corners, thin slits, a wall at a grazing angle, degenerate
// eyes and projections, and scene changes during the walk. Every non-approximate mode must answer
// a superset of what the rays see; failures print the frame, the object, where a ray saw it and
// the module's critical reason and δ.
//
// World: z up. Most views look along +y from the eye, so eye-space right = +x, up = +z.
#include "BoxScenes.h"
#include "ChangingScene.h"
#include "RayCastVisibility.h"
#include "TestHierarchies.h"

#include <osgVis/core/mask/MaskModule.h>
#include <osgVis/core/api/ModuleRegistry.h>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <sstream>
#include <string>

using namespace osgVis::core;
using osgVis::test::RayCastOptions;
using osgVis::test::RayCastResult;
using osgVis::test::RayCastVisibility;
using namespace osgVis::test;

namespace
{
using Reason = MaskModule::CriticalReason;

const char* reasonName(Reason r)
{
    switch (r)
    {
    case Reason::None: return "None";
    case Reason::First: return "First";
    case Reason::StampExpired: return "StampExpired";
    case Reason::LeftRegion: return "LeftRegion";
    case Reason::Turned: return "Turned";
    case Reason::OccluderGone: return "OccluderGone";
    case Reason::ViewChanged: return "ViewChanged";
    }
    return "?";
}

// ---- scenes ---------------------------------------------------------------------------------


// ---- views ----------------------------------------------------------------------------------

constexpr double Fovy = 60.0;

Mat4 perspective(double aspect, double nearDistance = 0.1, double fovyDegrees = Fovy)
{
    return glm::perspective(glm::radians(fovyDegrees), aspect, nearDistance, 1000.0);
}

View lookFrom(const Vec3& eye, const Vec3& direction, double time, std::uint32_t width, std::uint32_t height,
              const Mat4& projection)
{
    return makeView(glm::lookAt(eye, eye + direction, Vec3(0, 0, 1)), projection, time, width, height);
}

View lookAlongY(const Vec3& eye, double time, std::uint32_t width = 256, std::uint32_t height = 192)
{
    return lookFrom(eye, {0, 1, 0}, time, width, height, perspective(double(width) / height));
}

// The world point at view depth `depth` seen through window position (x, y) (pixels, bottom left).
Vec3 worldAt(const View& view, double x, double y, double depth)
{
    const Mat4 inverseProjection = glm::inverse(view.projectionMatrix);
    const double ndcX = 2.0 * x / view.viewportWidth - 1.0, ndcY = 2.0 * y / view.viewportHeight - 1.0;
    const Vec4 a4 = inverseProjection * Vec4(ndcX, ndcY, -1.0, 1.0), b4 = inverseProjection * Vec4(ndcX, ndcY, 1.0, 1.0);
    const Vec3 a = Vec3(a4) / a4.w, b = Vec3(b4) / b4.w;
    const double s = (-depth - a.z) / (b.z - a.z);
    const Vec4 world = glm::inverse(view.viewMatrix) * Vec4(a + s * (b - a), 1.0);
    return Vec3(world) / world.w;
}

// Size of one frame pixel at view depth `depth` (symmetric perspective).
double pixelSizeAt(const View& view, double depth)
{
    return 2.0 * depth / view.projectionMatrix[1][1] / view.viewportHeight;
}

// ---- checking -------------------------------------------------------------------------------

MaskModule& asMask(VisibilityModule& module)
{
    auto* mask = dynamic_cast<MaskModule*>(&module);
    if (!mask)
        throw std::logic_error(std::string("not a MaskModule: ") + module.name());
    return *mask;
}

VisibleSet cullAll(VisibilityModule& module, const Scene& scene, const View& view,
                   const std::vector<bool>& removed = {})
{
    VisibleSet visible(scene.objects.size(), true);
    for (std::size_t i = 0; i < removed.size(); ++i)
        if (removed[i])
            visible.clear(ObjectId(i));
    module.cull(view, visible);
    return visible;
}

std::string describe(const Scene& scene, const View& view, const MaskModule::Statistics& s)
{
    std::ostringstream out;
    out << "eye (" << view.eye.x << ", " << view.eye.y << ", " << view.eye.z << ") t=" << view.time << " viewport "
        << view.viewportWidth << "x" << view.viewportHeight << (view.orthographic ? " ortho" : "")
        << "; critical=" << reasonName(s.critical) << " delta=" << s.delta << " validUntil=" << s.validUntil
        << " occluders=" << s.occluderObjects << " mask " << s.maskWidth << "x" << s.maskHeight
        << " culled=" << s.culled << " of " << scene.objects.size();
    return out.str();
}

// Every object a ray sees must be in the answer. Names the first one that is not, with where the
// ray saw it.
testing::AssertionResult keepsEverythingSeen(const std::string& what, const Scene& scene, const View& view,
                                             const VisibleSet& answer, const RayCastResult& seen,
                                             const MaskModule::Statistics& stats)
{
    std::size_t missing = 0;
    std::ostringstream first;
    for (ObjectId id = 0; id < seen.visible.size(); ++id)
        if (seen.visible[id] && !answer.test(id))
        {
            if (missing++ == 0)
                first << "'" << scene.objects[id].name << "' (id " << id << ") seen at pixel (" << seen.seenAt[id].x
                      << ", " << seen.seenAt[id].y << ") depth " << seen.seenAtDepth[id];
        }
    if (missing == 0)
        return testing::AssertionSuccess();
    return testing::AssertionFailure() << what << ": " << missing << " visible object(s) culled, first " << first.str()
                                       << "\n  " << describe(scene, view, stats);
}

// One query checked against the rays; returns the answer.
VisibleSet cullAndCheck(const std::string& what, VisibilityModule& module, const Scene& scene, const View& view,
                        const std::vector<bool>& removed = {}, const RayCastOptions& rays = {})
{
    const VisibleSet answer = cullAll(module, scene, view, removed);
    const RayCastResult seen = RayCastVisibility(scene, removed).cast(view, rays);
    EXPECT_TRUE(keepsEverythingSeen(what, scene, view, answer, seen, asMask(module).lastStatistics()));
    return answer;
}

std::unique_ptr<VisibilityModule> makeMode(const std::string& mode)
{
    std::unique_ptr<VisibilityModule> module = createModule(mode);
    asMask(*module); // throws when the mode is not the mask module
    return module;
}

// ---- the reference itself ------------------------------------------------------------------

// The rays must get the basic cases right, or every test below proves nothing.
TEST(RayCastVisibility, SeesOnlyWhatIsInFront)
{
    Scene scene;
    const ObjectId wall = addBox(scene, {-5, 10, -5}, {5, 11, 5}, "wall");
    const ObjectId behind = addBox(scene, {-1, 20, -1}, {1, 21, 1}, "behind");
    const ObjectId aside = addBox(scene, {12, 20, -1}, {13, 21, 1}, "aside");
    const ObjectId outside = addBox(scene, {-1, -20, -1}, {1, -19, 1}, "behind the eye");
    const View view = lookAlongY({0, 0, 0}, 0.0, 160, 120);
    const RayCastResult seen = RayCastVisibility(scene).cast(view);
    EXPECT_EQ(seen.ids(), (std::vector<ObjectId>{wall, aside}));
    EXPECT_NEAR(seen.seenAtDepth[wall], 10.0, 1e-9);

    double depth = 0.0;
    EXPECT_EQ(RayCastVisibility(scene).objectAt(view, 80.0, 60.0, &depth), wall);
    EXPECT_NEAR(depth, 10.0, 1e-9);
    // Removed objects neither show nor hide.
    EXPECT_EQ(RayCastVisibility(scene, {true}).cast(view).ids(), (std::vector<ObjectId>{behind, aside}));
    // The near plane clips the wall away.
    const View clipped = lookFrom({0, 0, 0}, {0, 1, 0}, 0.0, 160, 120, perspective(4.0 / 3.0, 15.0));
    EXPECT_EQ(RayCastVisibility(scene).cast(clipped).ids(), (std::vector<ObjectId>{behind, aside}));
    // Orthographic rays are parallel: the box beside the wall shows, the one behind does not.
    const View ortho = lookFrom({0, 0, 0}, {0, 1, 0}, 0.0, 160, 120, glm::ortho(-20.0, 20.0, -15.0, 15.0, 0.1, 100.0));
    EXPECT_EQ(RayCastVisibility(scene).cast(ortho).ids(), (std::vector<ObjectId>{wall, aside}));
    (void)outside;
}

TEST(RayCastVisibility, CulledFacesNeitherShowNorHide)
{
    Scene scene;
    // The eye inside a shell, a box outside it.
    const ObjectId shell = addBox(scene, {-10, -10, -10}, {10, 10, 10}, "shell", OBJECT_CULL_BACK);
    const ObjectId box = addBox(scene, {-1, 20, -1}, {1, 21, 1}, "box");
    const View view = lookAlongY({0, 0, 0}, 0.0, 160, 120);
    EXPECT_EQ(RayCastVisibility(scene).cast(view).ids(), (std::vector<ObjectId>{box}));
    scene.objects[shell].flags = OBJECT_CULL_FRONT; // from inside, its faces are back faces: drawn
    EXPECT_EQ(RayCastVisibility(scene).cast(view).ids(), (std::vector<ObjectId>{shell}));
    scene.objects[shell].flags = OBJECT_NONE;
    EXPECT_EQ(RayCastVisibility(scene).cast(view).ids(), (std::vector<ObjectId>{shell}));
    scene.objects[shell].flags = OBJECT_TRANSPARENT;
    EXPECT_EQ(RayCastVisibility(scene).cast(view).ids(), (std::vector<ObjectId>{shell, box}));
}

// ---- city walk ------------------------------------------------------------------------------

// The walk down the street x = 85 (between block columns 2 and 3), looking along +y with a gentle
// sway of the gaze, 10 units/s sampled at 30 Hz.
std::vector<View> streetWalk(std::uint32_t width, std::uint32_t height, const Mat4& projection, int frames)
{
    std::vector<View> views;
    for (int f = 0; f < frames; ++f)
    {
        const double t = f / 30.0;
        const double yaw = glm::radians(12.0) * std::sin(0.6 * t);
        views.push_back(lookFrom({85.0 + 0.5 * std::sin(0.3 * t), -8.0 + 10.0 * t, 1.7},
                                 {std::sin(yaw), std::cos(yaw), -0.02}, t, width, height, projection));
    }
    return views;
}

TEST(MaskModule, CityWalkKeepsEverythingTheRaysSee)
{
    const City city = makeCity();
    const std::vector<View> walk = streetWalk(160, 120, perspective(160.0 / 120.0), 40);
    const RayCastVisibility rays(city.scene);
    std::vector<RayCastResult> seen;
    for (const View& view : walk)
        seen.push_back(rays.cast(view));

    for (const std::string mode : {"mask", "mask-distance"})
    {
        const std::unique_ptr<VisibilityModule> module = makeMode(mode);
        EXPECT_FALSE(module->approximate());
        ASSERT_LE(glm::length(walk[1].eye - walk[0].eye) / (walk[1].time - walk[0].time),
                  asMask(*module).options().maxEyeSpeed);
        module->setScene(city.scene);
        std::size_t failedFrames = 0, critical = 0, hidden = 0, culledHidden = 0;
        double deltaSum = 0.0;
        for (std::size_t f = 0; f < walk.size(); ++f)
        {
            const VisibleSet answer = cullAll(*module, city.scene, walk[f]);
            const MaskModule::Statistics stats = asMask(*module).lastStatistics();
            critical += stats.critical != Reason::None;
            deltaSum += stats.delta;
            for (ObjectId id = 0; id < city.scene.objects.size(); ++id)
                if (!seen[f].visible[id] && walk[f].frustum.classify(city.scene.objects[id].bounds) != Containment::Outside)
                {
                    ++hidden;
                    culledHidden += !answer.test(id);
                }
            const testing::AssertionResult ok = keepsEverythingSeen(
                mode + " frame " + std::to_string(f), city.scene, walk[f], answer, seen[f], stats);
            if (!ok && failedFrames++ == 0)
                ADD_FAILURE() << ok.message();
        }
        EXPECT_EQ(failedFrames, 0u) << mode << ": frames with a culled visible object";
        std::printf("[ %s ] city walk: %zu frames, %zu critical, mean delta %.4f, occlusion efficacy %.3f (%zu of %zu "
                    "hidden object-frames in the frustum culled)\n",
                    mode.c_str(), walk.size(), critical, deltaSum / walk.size(),
                    hidden ? double(culledHidden) / hidden : 0.0, culledHidden, hidden);
    }
}

// Looking down a street lined with buildings: the block behind the first row must be culled.
TEST(MaskModule, CullsTheBlockBehindTheStreetFront)
{
    const City city = makeCity();
    const View view = lookFrom({85.0, -8.0, 1.7}, {0, 1, 0}, 0.0, 160, 120, perspective(160.0 / 120.0));
    for (const std::string mode : {"mask", "mask-distance", "mask-approx"})
    {
        const std::unique_ptr<VisibilityModule> module = makeMode(mode);
        module->setScene(city.scene);
        const VisibleSet answer = mode == "mask-approx" ? cullAll(*module, city.scene, view)
                                                        : cullAndCheck(mode, *module, city.scene, view);
        // Buildings of block columns 1 and 4 (x 30..50 and 120..140) stand behind the street front
        // (columns 2 and 3) and inside the frustum.
        std::size_t culledInFrustum = 0, behind = 0;
        for (ObjectId id : city.buildings)
        {
            const Aabb& b = city.scene.objects[id].bounds;
            if ((b.min.x >= 30.0 && b.max.x <= 50.0) || (b.min.x >= 120.0 && b.max.x <= 140.0))
                if (view.frustum.classify(b) != Containment::Outside)
                {
                    ++behind;
                    culledInFrustum += !answer.test(id);
                }
        }
        std::printf("[ %s ] street view: %zu of %zu objects answered, %zu of %zu buildings behind the front culled\n",
                    mode.c_str(), answer.count(), city.scene.objects.size(), culledInFrustum, behind);
        EXPECT_GT(culledInFrustum, 0u) << mode << " culls nothing behind the street front";
        EXPECT_EQ(module->approximate(), mode == "mask-approx");
    }
}

TEST(MaskModule, PolygonBudgetBoundsWhatIsRasterized)
{
    // The street view again, with room for only the few largest polygons: fewer are rasterized,
    // and what is culled is still hidden.
    const City city = makeCity();
    const View view = lookFrom({85.0, -8.0, 1.7}, {0, 1, 0}, 0.0, 160, 120, perspective(160.0 / 120.0));
    MaskModule defaults, bounded([] {
        MaskOptions options;
        options.maxOccluderPolygons = 3;
        return options;
    }());
    defaults.setScene(city.scene);
    bounded.setScene(city.scene);
    const VisibleSet all = cullAndCheck("default budget", defaults, city.scene, view);
    const VisibleSet few = cullAndCheck("budget 3", bounded, city.scene, view);
    EXPECT_GT(defaults.lastStatistics().occluderPolygons, 3u);
    EXPECT_LE(bounded.lastStatistics().occluderPolygons, 3u);
    EXPECT_GT(bounded.lastStatistics().occluderPolygons, 0u);
    EXPECT_GE(few.count(), all.count());
    EXPECT_LT(few.count(), city.scene.objects.size()) << "the largest three still hide something";
}

// ---- the δ-ball -----------------------------------------------------------------------------

// A wall whose corner projects to window position `corner` from the critical eye (looking along +y,
// wall at depth WallDepth) and covers the frame on the inner side (towards -outward), with small
// targets far behind it, barely hidden: squares of 1 pixel at `offsets` pixels inside the corner,
// on the diagonal and along both edges.
struct CornerScene
{
    Scene scene;
    ObjectId wall = InvalidObject;
    std::vector<ObjectId> targets;
    std::vector<glm::dvec2> targetOffsets; // pixels inside the corner (x, y)
};

constexpr double WallDepth = 10.0, TargetDepth = 80.0;

CornerScene makeCornerScene(const View& critical, const glm::dvec2& corner, const glm::dvec2& outward)
{
    CornerScene c;
    const Vec3 wallCorner = worldAt(critical, corner.x, corner.y, WallDepth);
    const double far = 20.0 * WallDepth;
    const Vec3 inner(-outward.x * far, 0.0, -outward.y * far);
    const Vec3 a = wallCorner, b = wallCorner + inner + Vec3(0, 0.3, 0);
    c.wall = addBox(c.scene, glm::min(a, b), glm::max(a, b), "wall");
    const double offsets[] = {0.5, 1, 2, 3, 4, 5, 6, 7, 8, 10, 12, 14, 16, 20, 24, 28};
    for (double s : offsets)
        for (const glm::dvec2 at : {glm::dvec2(s, s), glm::dvec2(s, 30.0), glm::dvec2(30.0, s)})
        {
            // Pixel square [at, at + 1] inside the corner, at the target depth.
            const glm::dvec2 p0 = corner - outward * at, p1 = corner - outward * (at + 1.0);
            const Vec3 q0 = worldAt(critical, p0.x, p0.y, TargetDepth), q1 = worldAt(critical, p1.x, p1.y, TargetDepth);
            const Vec3 lo = glm::min(q0, q1), hi = glm::max(q0, q1) + Vec3(0, 0.5, 0);
            c.targets.push_back(addBox(c.scene, lo, hi,
                                       "target (" + std::to_string(at.x) + ", " + std::to_string(at.y) + ") px in"));
            c.targetOffsets.push_back(at);
        }
    return c;
}

// Rays only over the region of the targets (they lie within 31 pixels of the corner).
RayCastOptions cornerRays(const View& view, const glm::dvec2& corner)
{
    RayCastOptions r;
    r.x0 = std::uint32_t(std::max(0.0, corner.x - 40.0));
    r.y0 = std::uint32_t(std::max(0.0, corner.y - 40.0));
    r.x1 = std::uint32_t(std::min(double(view.viewportWidth), corner.x + 40.0));
    r.y1 = std::uint32_t(std::min(double(view.viewportHeight), corner.y + 40.0));
    return r;
}

void checkDeltaBall(const MaskOptions& options, const std::string& label)
{
    const std::uint32_t width = 256, height = 192;
    const Vec3 eye(0.0, 0.0, 0.0);
    const double tc = 1.0;
    const View critical = lookAlongY(eye, tc, width, height);

    struct Place
    {
        const char* name;
        glm::dvec2 corner, outward;
    };
    // Wall corners at 90% of the way to the frame corners, and (control) at the centre.
    const double mx = 0.05 * width, my = 0.05 * height;
    const Place places[] = {
        {"top right", {width - mx, height - my}, {1, 1}}, {"top left", {mx, height - my}, {-1, 1}},
        {"bottom left", {mx, my}, {-1, -1}},              {"bottom right", {width - mx, my}, {1, -1}},
        {"centre", {width / 2.0, height / 2.0}, {1, 1}},
    };
    for (const Place& place : places)
    {
        const CornerScene c = makeCornerScene(critical, place.corner, place.outward);
        const RayCastVisibility rays(c.scene);
        const RayCastOptions region = cornerRays(critical, place.corner);
        const RayCastResult seenFromCritical = rays.cast(critical, region);
        // Scene check: the wall hides every target from the critical eye.
        for (ObjectId id : c.targets)
            ASSERT_FALSE(seenFromCritical.visible[id]) << place.name << ": " << c.scene.objects[id].name;

        const Vec3 right(place.outward.x, 0, 0), up(0, 0, place.outward.y), back(0, -1, 0);
        const std::pair<const char*, Vec3> moves[] = {
            {"sideways", right},
            {"up", up},
            {"diagonal", glm::normalize(right + up)},
            {"backwards", back},
            {"back diagonal", glm::normalize(right + up + back)},
            {"forwards", -back},
            {"sideways inwards", -right},
        };
        std::size_t culledAtCritical = 0, exposedSomewhere = 0;
        double nearestCulled = 1e9, farthestExposed = 0.0;
        for (const auto& [moveName, direction] : moves)
        {
            MaskModule module(options);
            module.setScene(c.scene);
            const std::string what = label + " " + place.name + " " + moveName;
            const VisibleSet atCritical = cullAll(module, c.scene, critical);
            const MaskModule::Statistics s = module.lastStatistics();
            EXPECT_TRUE(keepsEverythingSeen(what + " (critical eye)", c.scene, critical, atCritical, seenFromCritical, s));
            ASSERT_EQ(s.critical, Reason::First) << what;
            ASSERT_GT(s.delta, 0.0) << what;
            ASSERT_NEAR(s.validUntil, tc + s.delta / options.maxEyeSpeed, 1e-9 * (1.0 + s.validUntil)) << what;
            if (std::string(moveName) == "sideways")
                for (std::size_t i = 0; i < c.targets.size(); ++i)
                    if (!atCritical.test(c.targets[i]))
                    {
                        ++culledAtCritical;
                        nearestCulled = std::min(nearestCulled, std::min(c.targetOffsets[i].x, c.targetOffsets[i].y));
                    }

            // On the boundary of the δ-ball, same view direction, before the stamps expire.
            const double midValidity = tc + 0.5 * (s.validUntil - tc);
            const View displaced = lookAlongY(eye + 0.999 * s.delta * direction, midValidity, width, height);
            const VisibleSet answer = cullAll(module, c.scene, displaced);
            const RayCastResult seen = rays.cast(displaced, region);
            EXPECT_EQ(module.lastStatistics().critical, Reason::None)
                << what << ": an eye inside the δ-ball must be answered from the stamps";
            EXPECT_TRUE(keepsEverythingSeen(what + " (eye at 0.999 delta)", c.scene, displaced, answer, seen,
                                            module.lastStatistics()));
            for (std::size_t i = 0; i < c.targets.size(); ++i)
                if (seen.visible[c.targets[i]])
                {
                    ++exposedSomewhere;
                    farthestExposed = std::max(farthestExposed, std::min(c.targetOffsets[i].x, c.targetOffsets[i].y));
                }

            // Outside the ball (faster than V): a new critical frame, still correct.
            const View outside = lookAlongY(eye + 1.5 * s.delta * direction, midValidity, width, height);
            const VisibleSet outsideAnswer = cullAll(module, c.scene, outside);
            EXPECT_EQ(module.lastStatistics().critical, Reason::LeftRegion) << what;
            EXPECT_TRUE(keepsEverythingSeen(what + " (eye at 1.5 delta)", c.scene, outside, outsideAnswer,
                                            rays.cast(outside, region), module.lastStatistics()));
        }
        std::printf("[ %s ] %s: %zu of %zu targets culled at the critical eye (nearest %.1f px inside); "
                    "%zu target sightings from the ball's boundary (deepest %.1f px inside)\n",
                    label.c_str(), place.name, culledAtCritical, c.targets.size(), nearestCulled, exposedSomewhere,
                    farthestExposed);
        // Not vacuous: the mask hides targets near this corner, and moving inside the ball does expose
        // some of the targets (those the shrinkage left unmarked).
        EXPECT_GT(culledAtCritical, 0u) << label << " " << place.name;
        EXPECT_GT(exposedSomewhere, 0u) << label << " " << place.name;
    }
}

TEST(MaskModule, DeltaBallBoundaryAtFrameCornersFullResolutionMask)
{
    MaskOptions options;
    options.shrinkPixels = 8.0;
    options.maskDownscale = 1;
    checkDeltaBall(options, "mask 1:1 shrink 8");
}

TEST(MaskModule, DeltaBallBoundaryAtFrameCornersDefaultOptions)
{
    checkDeltaBall(MaskOptions{}, "mask defaults");
}

TEST(MaskModule, DeltaBallBoundaryWithDistanceMeasure)
{
    MaskOptions options;
    options.measure = OccluderMeasure::Distance;
    options.shrinkPixels = 2.0;
    options.maskDownscale = 2;
    checkDeltaBall(options, "mask-distance shrink 2");
}

// ---- thin slits -----------------------------------------------------------------------------

// Two walls at depth 10 with a gap of 1/5 of a mask pixel, a target far behind the gap. `vertical`:
// the gap runs up and down; `oneObject`: both walls are one object.
void checkSlit(bool vertical, bool oneObject, double screenOffset)
{
    const std::uint32_t width = 256, height = 192;
    const View view = lookAlongY({0, 0, 0}, 1.0, width, height);
    MaskOptions options; // mask pixel = maskDownscale frame pixels
    const double gap = 0.2 * options.maskDownscale * pixelSizeAt(view, WallDepth);
    const double far = 100.0, offset = screenOffset * WallDepth; // slit position across the screen
    const double thickness = 0.2 * gap; // thin plates: a thick wall closes a slit seen at an angle
    Scene scene;
    // Coordinates across the slit (u) and along it (v): u is x for a vertical slit, z otherwise.
    const auto point = [&](double u, double depth, double v) { return vertical ? Vec3(u, depth, v) : Vec3(v, depth, u); };
    const std::vector<Triangle> a = boxTriangles(point(-far, WallDepth, -far), point(offset - gap / 2, WallDepth + thickness, far));
    const std::vector<Triangle> b = boxTriangles(point(offset + gap / 2, WallDepth, -far), point(far, WallDepth + thickness, far));
    if (oneObject)
    {
        std::vector<Triangle> both = a;
        both.insert(both.end(), b.begin(), b.end());
        addTriangles(scene, both, "walls");
    }
    else
    {
        addTriangles(scene, a, "wall a");
        addTriangles(scene, b, "wall b");
    }
    const double behind = 5.0 * WallDepth, reach = behind / WallDepth;
    const ObjectId target = addBox(scene, point(offset * reach - 2.0, behind, -2.0), point(offset * reach + 2.0, behind + 1.0, 2.0),
                                   "target behind the slit");
    const RayCastResult seen = RayCastVisibility(scene).cast(view);
    ASSERT_TRUE(seen.visible[target]) << "scene: the rays must see the target through the slit";
    for (const std::string mode : {"mask", "mask-distance"})
    {
        const std::unique_ptr<VisibilityModule> module = makeMode(mode);
        module->setScene(scene);
        const VisibleSet answer = cullAll(*module, scene, view);
        EXPECT_TRUE(keepsEverythingSeen(mode + " slit", scene, view, answer, seen, asMask(*module).lastStatistics()));
        EXPECT_TRUE(answer.test(target)) << mode;
    }
}

TEST(MaskModule, KeepsTargetSeenThroughVerticalSlit) { checkSlit(true, false, 0.0); }
TEST(MaskModule, KeepsTargetSeenThroughHorizontalSlit) { checkSlit(false, false, 0.0); }
TEST(MaskModule, KeepsTargetSeenThroughSlitInOneObject) { checkSlit(true, true, 0.0); }
TEST(MaskModule, KeepsTargetSeenThroughSlitOffCentre) { checkSlit(true, false, 0.5); }

// ---- grazing wall ---------------------------------------------------------------------------

// A 200-long wall 2 units to the right of the eye, seen almost edge-on, with small boxes in front
// of it and behind it around its far end: the wall's depth changes by tens of units across one
// pixel there, so a mask with the depth at pixel centres would hide boxes standing in front of it.
TEST(MaskModule, GrazingWallHidesOnlyWhatIsBehindIt)
{
    Scene scene;
    addBox(scene, {2.0, 1.0, 0.0}, {2.2, 200.0, 6.0}, "long wall");
    for (double x : {1.5, 1.85, 2.3, 2.5, 2.8, 3.5})
        for (double y : {120.0, 170.0, 190.0, 196.0, 199.0, 201.0, 203.0, 206.0, 212.0, 225.0})
            addBox(scene, {x - 0.1, y, 1.0}, {x + 0.1, y + 0.3, 1.4},
                   "box x=" + std::to_string(x) + " y=" + std::to_string(y));
    std::vector<View> views;
    std::vector<RayCastResult> seen;
    for (int f = 0; f < 6; ++f)
    {
        views.push_back(lookAlongY({0.0, 2.0 * f, 1.7}, 1.0 + 0.2 * f, 160, 120));
        seen.push_back(RayCastVisibility(scene).cast(views.back()));
    }
    for (const double shrink : {0.0, 4.0})
        for (const std::uint32_t downscale : {1u, 4u})
        {
            MaskOptions options;
            options.shrinkPixels = shrink;
            options.maskDownscale = downscale;
            MaskModule module(options);
            module.setScene(scene);
            for (std::size_t f = 0; f < views.size(); ++f)
            {
                const VisibleSet answer = cullAll(module, scene, views[f]);
                EXPECT_TRUE(keepsEverythingSeen("grazing shrink " + std::to_string(shrink) + " downscale " +
                                                    std::to_string(downscale) + " frame " + std::to_string(f),
                                                scene, views[f], answer, seen[f], module.lastStatistics()));
            }
        }
}

// ---- degenerate eyes and projections --------------------------------------------------------

// Boxes behind a building at x 0..10, y 10..20, height 10, for the eye cases below.
Scene buildingWithBoxesBehind(std::uint32_t buildingFlags = OBJECT_NONE)
{
    Scene scene;
    addBox(scene, {0, 10, 0}, {10, 20, 10}, "building", buildingFlags);
    for (int i = 0; i < 5; ++i)
        addBox(scene, {1.0 + 2.0 * i, 30, 0}, {1.5 + 2.0 * i, 30.5, 2.0 + i}, "box " + std::to_string(i));
    addBox(scene, {-20, 40, 0}, {30, 41, 30}, "backdrop");
    return scene;
}

void checkViews(const std::string& what, const Scene& scene, const std::vector<View>& views)
{
    const RayCastVisibility rays(scene);
    std::vector<RayCastResult> seen;
    for (const View& view : views)
        seen.push_back(rays.cast(view));
    for (const std::string mode : {"mask", "mask-distance"})
    {
        const std::unique_ptr<VisibilityModule> module = makeMode(mode);
        module->setScene(scene);
        for (std::size_t f = 0; f < views.size(); ++f)
        {
            const VisibleSet answer = cullAll(*module, scene, views[f]);
            EXPECT_TRUE(keepsEverythingSeen(mode + " " + what + " view " + std::to_string(f), scene, views[f], answer,
                                            seen[f], asMask(*module).lastStatistics()));
        }
    }
}

TEST(MaskModule, EyeOnAnOccludersPlane)
{
    const Scene scene = buildingWithBoxesBehind();
    // On the plane of the front face (y = 10), of a side face (x = 0) and of the roof (z = 10).
    checkViews("eye on planes", scene,
               {lookFrom({5, 10, 2}, {0.3, 1, 0}, 0.0, 160, 120, perspective(4.0 / 3.0)),
                lookFrom({0, 0, 2}, {0, 1, 0}, 0.1, 160, 120, perspective(4.0 / 3.0)),
                lookFrom({5, 0, 10}, {0, 1, 0}, 0.2, 160, 120, perspective(4.0 / 3.0)),
                lookFrom({10, 5, 10}, {0, 1, -0.1}, 0.3, 160, 120, perspective(4.0 / 3.0))});
}

TEST(MaskModule, EyeInsideABuilding)
{
    for (const std::uint32_t flags : {std::uint32_t(OBJECT_NONE), std::uint32_t(OBJECT_CULL_BACK)})
    {
        const Scene scene = buildingWithBoxesBehind(flags);
        const View inside = lookFrom({5, 15, 2}, {0, 1, 0}, 0.0, 160, 120, perspective(4.0 / 3.0));
        // Scene check: seen from inside, back faces are not drawn, so the boxes show only then.
        ASSERT_EQ(RayCastVisibility(scene).cast(inside).visible[1], flags == OBJECT_CULL_BACK);
        checkViews(flags ? "inside, back faces culled" : "inside", scene,
                   {inside, lookFrom({5, 15.5, 2}, {0.2, 1, 0}, 0.1, 160, 120, perspective(4.0 / 3.0))});
    }
}

TEST(MaskModule, OccluderStraddlingTheNearPlane)
{
    for (const std::uint32_t flags : {std::uint32_t(OBJECT_NONE), std::uint32_t(OBJECT_CULL_BACK)})
    {
        const Scene scene = buildingWithBoxesBehind(flags);
        // Near plane 1.0 cuts the building's front face (y = 10) off: the eye sees into it.
        const Mat4 projection = perspective(4.0 / 3.0, 1.0);
        const View view = lookFrom({5, 9.5, 3}, {0, 1, 0}, 0.0, 160, 120, projection);
        ASSERT_EQ(RayCastVisibility(scene).cast(view).visible[1], flags == OBJECT_CULL_BACK);
        checkViews(flags ? "near plane, back faces culled" : "near plane", scene,
                   {view, lookFrom({5, 9.4, 3}, {0, 1, 0}, 0.05, 160, 120, projection)});
    }
    // A single slanted wall (no volume, facing the eye at 26 degrees) that the near plane (1.0) cuts
    // off on the left of the frame, where it passes nearer than 1.0; boxes behind show there.
    Scene scene;
    std::vector<Triangle> wall;
    const Vec3 a(-2, 0.2, -5), b(10, 6, -5), c(10, 6, 15), d(-2, 0.2, 15);
    wall.push_back({Vec3f(a), Vec3f(b), Vec3f(c)});
    wall.push_back({Vec3f(a), Vec3f(c), Vec3f(d)});
    addTriangles(scene, wall, "slanted wall");
    for (int i = 0; i < 6; ++i)
        addBox(scene, {-14.0 + 2.0 * i, 20, 0}, {-13.0 + 2.0 * i, 21, 3}, "box " + std::to_string(i));
    const View view = lookFrom({0, 0, 2}, {0, 1, 0}, 0.0, 160, 120, perspective(4.0 / 3.0, 1.0));
    const RayCastResult seen = RayCastVisibility(scene).cast(view);
    ASSERT_TRUE(seen.visible[1]) << "scene: the clipped part shows box 0";
    ASSERT_FALSE(seen.visible[6]) << "scene: the wall hides box 5";
    checkViews("slanted wall through the near plane", scene, {view});
}

TEST(MaskModule, OrthographicViews)
{
    const City city = makeCity();
    const Mat4 ortho = glm::ortho(-30.0, 30.0, -22.5, 22.5, 0.1, 400.0);
    checkViews("orthographic", city.scene, streetWalk(160, 120, ortho, 6));
    checkViews("orthographic from above", city.scene,
               {lookFrom({80, 80, 100}, {0.1, 0.2, -1}, 0.0, 160, 120, ortho)});
}

TEST(MaskModule, OffCentreProjection)
{
    const City city = makeCity();
    // Asymmetric frustum: the view axis runs near the left and bottom edges of the frame.
    const Mat4 offCentre = glm::frustum(-0.02, 0.12, -0.015, 0.075, 0.1, 1000.0);
    checkViews("off-centre", city.scene, streetWalk(160, 120, offCentre, 8));
}

// A turn must forget the marks even when stamps ran out at the same moment: marks judged objects
// by their part inside the critical frame, and nodes outside the frustum were stamped as out of
// view for the critical orientation only. (Expiry used to be checked first and kept them.)
TEST(MaskModule, TurnAtStampExpiryForgetsTheMarks)
{
    const City city = makeCity();
    const Vec3 eye(85.0, -8.0, 1.7);
    for (const std::string mode : {"mask", "mask-distance"})
        for (const Vec3& direction : {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(1, 1, 0), Vec3(0, -1, 0)})
        {
            const std::unique_ptr<VisibilityModule> module = makeMode(mode);
            module->setScene(city.scene);
            cullAndCheck(mode + " before the turn", *module, city.scene,
                         lookFrom(eye, {0, 1, 0}, 0.0, 160, 120, perspective(4.0 / 3.0)));
            const MaskModule::Statistics first = asMask(*module).lastStatistics();
            ASSERT_GT(first.criticalAfter, 0.0) << describe(city.scene, lookAlongY(eye, 0.0), first);
            const View turned = lookFrom(eye, direction, first.criticalAfter, 160, 120, perspective(4.0 / 3.0));
            cullAndCheck(mode + " after the turn", *module, city.scene, turned);
            EXPECT_EQ(asMask(*module).lastStatistics().critical, MaskModule::CriticalReason::Turned)
                << describe(city.scene, turned, asMask(*module).lastStatistics());
        }
}

TEST(MaskModule, ViewportChangeBetweenFrames)
{
    const City city = makeCity();
    const Vec3 eye(85.0, -8.0, 1.7);
    // A window resized wider (the projection follows), then only the viewport changes; the times
    // are close enough that no stamp expires in between.
    const std::vector<View> views = {lookFrom(eye, {0, 1, 0}, 0.0, 160, 120, perspective(4.0 / 3.0)),
                                     lookFrom(eye, {0, 1, 0}, 1e-5, 240, 120, perspective(2.0)),
                                     lookFrom(eye, {0, 1, 0}, 2e-5, 120, 120, perspective(2.0))};
    std::vector<RayCastResult> seen;
    for (const View& view : views)
        seen.push_back(RayCastVisibility(city.scene).cast(view));
    for (const std::string mode : {"mask", "mask-distance"})
    {
        const std::unique_ptr<VisibilityModule> module = makeMode(mode);
        module->setScene(city.scene);
        for (std::size_t f = 0; f < views.size(); ++f)
        {
            const VisibleSet answer = cullAll(*module, city.scene, views[f]);
            const MaskModule::Statistics stats = asMask(*module).lastStatistics();
            EXPECT_TRUE(keepsEverythingSeen(mode + " viewport change " + std::to_string(f), city.scene, views[f],
                                            answer, seen[f], stats));
            EXPECT_EQ(stats.critical, f == 0 ? Reason::First : Reason::ViewChanged) << mode << " view " << f;
        }
    }
}

// ---- dynamic scenes -------------------------------------------------------------------------

// The street front (ChangingScene.h), eye at (0, -20, 5) looking along +y (the front spans image x
// within ±0.5 of the depth; open places lie beyond). Changes go either to the scene in place
// (sceneChanged) or to a copy (sceneReplaced), the copies kept alive as the module may hold any.
// Each test runs with both occluder measures, and on a renderer's kd-tree recorded before the
// changes (which no longer holds what moved or came in).
enum class DynamicSetup
{
    Coverage,
    Distance,
    CoverageOnRendererKdTree,
};

class Dynamic : public testing::TestWithParam<DynamicSetup>
{
protected:
    // A fresh scene and module (each test runs both ways of telling the module about changes).
    void reset()
    {
        StreetFront street = makeStreetFront();
        front = street.front;
        open = street.open;
        hiddenBoxes = street.hiddenBoxes;
        if (GetParam() == DynamicSetup::CoverageOnRendererKdTree)
            street.scene.hierarchy = kdTreeOf(street.scene);
        scenes.reset(std::move(street.scene));
        module = makeMode(GetParam() == DynamicSetup::Distance ? "mask-distance" : "mask");
        module->setScene(scene_());
        EXPECT_EQ(asMask(*module).walksSceneHierarchy(), GetParam() == DynamicSetup::CoverageOnRendererKdTree);
    }
    const Scene& scene_() const { return scenes.current(); }
    View at(double time, const Vec3& eye = {0, -20, 5}) const { return lookAlongY(eye, time, 160, 120); }

    VisibleSet check(const std::string& what, const View& view)
    {
        return cullAndCheck(what, *module, scene_(), view, scenes.removed());
    }
    // The critical frame everything starts from; the boxes behind the front must be culled there,
    // or the tests below would prove nothing.
    void startWalk()
    {
        const VisibleSet first = check("critical frame", at(1.0));
        ASSERT_EQ(stats().critical, Reason::First);
        for (ObjectId id : hiddenBoxes)
            ASSERT_FALSE(first.test(id)) << scene_().objects[id].name << " not culled behind the street front";
    }
    void change(SceneChange::Kind kind, std::vector<ObjectId> ids, const std::function<void(Scene&)>& mutate,
                bool replace)
    {
        scenes.change(*module, kind, std::move(ids), mutate, replace);
    }
    MaskModule::Statistics stats() const { return asMask(*module).lastStatistics(); }

    ChangingScene scenes;
    std::unique_ptr<VisibilityModule> module;
    ObjectId front = InvalidObject, open = InvalidObject;
    std::vector<ObjectId> hiddenBoxes;
};

TEST_P(Dynamic, InsertedObjectsAreNeverWronglyHidden)
{
    for (const bool replace : {false, true})
    {
        reset();
        ASSERT_NO_FATAL_FAILURE(startWalk());
        ObjectId behind = InvalidObject, tower = InvalidObject, inOpen = InvalidObject;
        change(SceneChange::Kind::Inserted, {ObjectId(scene_().objects.size()), ObjectId(scene_().objects.size() + 1),
                                             ObjectId(scene_().objects.size() + 2)},
               [&](Scene& s)
               {
                   behind = addBox(s, {-1, 22, 0}, {0, 23, 2}, "inserted behind");
                   // In the hidden region's kd-tree nodes, but tall enough to rise above the front.
                   tower = addBox(s, {3, 21, 0}, {4, 22, 40}, "inserted tower");
                   inOpen = addBox(s, {-26, 20, 0}, {-25, 21, 2}, "inserted in the open");
               },
               replace);
        for (int f = 1; f <= 4; ++f)
        {
            const VisibleSet answer = check("after insert frame " + std::to_string(f), at(1.0 + 0.02 * f));
            EXPECT_TRUE(answer.test(tower)) << "replace=" << replace;
            EXPECT_TRUE(answer.test(inOpen)) << "replace=" << replace;
        }
        (void)behind;
        // After the stamps expired a new critical frame may hide the inserted box behind the front.
        check("after insert, next critical frame", at(1.0 + 1e3));
    }
}

TEST_P(Dynamic, HiddenObjectMovedIntoTheOpenShowsAtOnce)
{
    for (const bool replace : {false, true})
    {
        reset();
        ASSERT_NO_FATAL_FAILURE(startWalk());
        const ObjectId moved = hiddenBoxes[1];
        change(SceneChange::Kind::Moved, {moved}, [&](Scene& s) { reshapeBox(s, moved, {24, 20, 0}, {25, 21, 2}); },
               replace);
        const VisibleSet answer = check("moved into the open", at(1.01));
        EXPECT_TRUE(answer.test(moved)) << "replace=" << replace;
        // And moved again (the kd-tree only grows its boxes lazily).
        change(SceneChange::Kind::Moved, {moved}, [&](Scene& s) { reshapeBox(s, moved, {-28, 25, 0}, {-27, 26, 2}); },
               replace);
        EXPECT_TRUE(check("moved again", at(1.02)).test(moved)) << "replace=" << replace;
    }
}

TEST_P(Dynamic, DeletedOccluderBringsBackWhatItHid)
{
    for (const bool replace : {false, true})
    {
        reset();
        ASSERT_NO_FATAL_FAILURE(startWalk());
        change(SceneChange::Kind::Removed, {front}, [](Scene&) {}, replace);
        const VisibleSet answer = check("occluder deleted", at(1.01));
        EXPECT_EQ(stats().critical, Reason::OccluderGone) << "replace=" << replace;
        for (ObjectId id : hiddenBoxes)
            EXPECT_TRUE(answer.test(id)) << scene_().objects[id].name << " replace=" << replace;
    }
}

TEST_P(Dynamic, MovedOccluderNeverOccludesAgain)
{
    for (const bool replace : {false, true})
    {
        reset();
        ASSERT_NO_FATAL_FAILURE(startWalk());
        // Shifted by 0.5: it still hides the boxes, but it moves now, so it may never hide anything.
        change(SceneChange::Kind::Moved, {front}, [&](Scene& s) { reshapeBox(s, front, {-9.5, 0, 0}, {10.5, 10, 15}); },
               replace);
        check("occluder moved", at(1.01));
        EXPECT_EQ(stats().critical, Reason::OccluderGone) << "replace=" << replace;
        for (const double t : {1.02, 1e3, 2e3})
        {
            const VisibleSet answer = check("after the occluder moved, t=" + std::to_string(t), at(t));
            for (ObjectId id : hiddenBoxes)
                EXPECT_TRUE(answer.test(id)) << scene_().objects[id].name << " hidden by a moved occluder at t=" << t
                                             << " replace=" << replace;
        }
        // The open box moved a little stays visible too (moved objects in the open).
        change(SceneChange::Kind::Moved, {open}, [&](Scene& s) { reshapeBox(s, open, {25, 22, 0}, {26, 23, 2}); },
               replace);
        EXPECT_TRUE(check("open box moved", at(2e3 + 0.01)).test(open));
    }
}

INSTANTIATE_TEST_SUITE_P(MaskModule, Dynamic,
                         testing::Values(DynamicSetup::Coverage, DynamicSetup::Distance,
                                         DynamicSetup::CoverageOnRendererKdTree),
                         [](const testing::TestParamInfo<DynamicSetup>& info)
                         {
                             return info.param == DynamicSetup::Coverage   ? "Coverage"
                                    : info.param == DynamicSetup::Distance ? "Distance"
                                                                           : "OnRendererKdTree";
                         });

// ---- mask-approx ----------------------------------------------------------------------------

TEST(MaskModule, ApproxRunsAndCullsOnTheWalk)
{
    const City city = makeCity();
    const std::unique_ptr<VisibilityModule> module = makeMode("mask-approx");
    EXPECT_TRUE(module->approximate());
    EXPECT_EQ(asMask(*module).options().shrink, MaskShrink::FusedUnion);
    module->setScene(city.scene);
    std::size_t culled = 0;
    for (const View& view : streetWalk(160, 120, perspective(4.0 / 3.0), 20))
        culled += city.scene.objects.size() - cullAll(*module, city.scene, view).count();
    EXPECT_GT(culled, 0u);
}
} // namespace
