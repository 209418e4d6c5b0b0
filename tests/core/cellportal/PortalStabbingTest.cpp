// SPDX-License-Identifier: MIT
// Portal line stabbing: zero false rejections on thousands of sequences built around real lines
// (and sightlines from real eyes), rejection of configurations no line passes, degenerate input,
// and the measured looseness against a brute-force line search.
#include <osgVis/core/cellportal/PortalStabbing.h>

#include "AllocationCounter.h"

#include "AllocationCounter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <thread>
#include <vector>

using namespace osgVis::core;

namespace
{
constexpr double Tolerance = 1e-5; // 1e-6 x the ~10-unit scenes below

OrientedPortal portal(int axis, double coordinate, double uMin, double uMax, double vMin, double vMax,
                      bool positive = true)
{
    OrientedPortal p;
    p.rect.axis = static_cast<std::uint8_t>(axis);
    p.rect.coordinate = coordinate;
    p.rect.uMin = uMin;
    p.rect.uMax = uMax;
    p.rect.vMin = vMin;
    p.rect.vMax = vMax;
    p.positive = positive;
    return p;
}

// A door in the plane y = c crossed towards +y, spanning x in [x0, x1] and z in [z0, z1]
// (for axis y, u is z and v is x).
OrientedPortal yDoor(double c, double x0, double x1, double z0 = 0.0, double z1 = 1.0, bool positive = true)
{
    return portal(1, c, z0, z1, x0, x1, positive);
}

// A door in the plane x = c crossed towards +x, spanning y in [y0, y1] and z in [z0, z1].
OrientedPortal xDoor(double c, double y0, double y1, double z0 = 0.0, double z1 = 1.0, bool positive = true)
{
    return portal(0, c, y0, y1, z0, z1, positive);
}

bool stabbable(const std::vector<OrientedPortal>& portals)
{
    return portalSequenceStabbable(portals.data(), portals.size(), Tolerance);
}

Aabb cubeAround(const Vec3& p, double halfSize)
{
    return {p - Vec3(halfSize), p + Vec3(halfSize)};
}

struct RandomLineCase
{
    Vec3 origin;
    Vec3 direction;
    std::vector<double> parameters; // where the line crosses each portal
    std::vector<OrientedPortal> portals;
};

// Portals of random axis and size (1e-3 to 5) around the points where a line crosses them, the
// crossing point often on an edge or corner.
class RandomLines
{
public:
    explicit RandomLines(unsigned seed) : _rng(seed) {}

    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(_rng); }
    Vec3 unitVector()
    {
        for (;;)
        {
            const Vec3 v(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
            const double l = glm::length(v);
            if (l > 0.1 && l <= 1.0)
                return v / l;
        }
    }

    RandomLineCase make(int count, double firstParameter)
    {
        RandomLineCase c;
        c.origin = Vec3(uniform(-10, 10), uniform(-10, 10), uniform(-10, 10));
        c.direction = unitVector();
        double lambda = firstParameter;
        for (int i = 0; i < count; ++i)
        {
            int axis = static_cast<int>(_rng() % 3);
            while (std::fabs(c.direction[axis]) < 1e-3)
                axis = (axis + 1) % 3;
            const Vec3 x = c.origin + lambda * c.direction;
            OrientedPortal p;
            p.rect.axis = static_cast<std::uint8_t>(axis);
            p.rect.coordinate = x[axis];
            p.positive = c.direction[axis] > 0.0;
            p.rect.uMin = around(x[AxialRect::uAxis(axis)], p.rect.uMax);
            p.rect.vMin = around(x[AxialRect::vAxis(axis)], p.rect.vMax);
            c.portals.push_back(p);
            c.parameters.push_back(lambda);
            lambda += (_rng() % 4 == 0) ? uniform(1e-3, 1e-2) : uniform(0.01, 5.0);
        }
        return c;
    }

private:
    // A range containing `x`: random size, x at a random place, an end or very near one.
    double around(double x, double& hi)
    {
        const double size = (_rng() % 4 == 0) ? 1e-3 : std::exp(uniform(std::log(1e-3), std::log(5.0)));
        double fraction = uniform(0.0, 1.0);
        switch (_rng() % 6)
        {
        case 0:
            fraction = 0.0;
            break;
        case 1:
            fraction = 1.0;
            break;
        case 2:
            fraction = 1e-9;
            break;
        default:
            break;
        }
        const double lo = x - fraction * size;
        hi = lo + size;
        return lo;
    }

    std::mt19937 _rng;
};
} // namespace

TEST(PortalStabbing, ShortSequencesAndPortalsBehind)
{
    EXPECT_TRUE(portalSequenceStabbable(nullptr, 0, Tolerance));
    const OrientedPortal one = yDoor(0, 0, 1);
    EXPECT_TRUE(portalSequenceStabbable(&one, 1, Tolerance));
    EXPECT_TRUE(stabbable({yDoor(0, 0, 1), yDoor(3, 40, 41)}));
    EXPECT_TRUE(stabbable({yDoor(0, 0, 1), xDoor(5, 30, 31)}));
    // Portal 1 lies wholly behind portal 0's plane (y < 0): no line crosses 0 and then 1.
    EXPECT_FALSE(stabbable({yDoor(0, 0, 1), yDoor(-1, 0, 1)}));
    EXPECT_FALSE(stabbable({yDoor(0, 0, 1), xDoor(0.5, -3, -1)}));
    // Touching within tolerance still counts.
    EXPECT_TRUE(stabbable({yDoor(0, 0, 1), xDoor(0.5, -3, 0.5 * Tolerance)}));
}

TEST(PortalStabbing, ZigZagOfDoorsIsRejected)
{
    //   y=2  [0,1]
    //   y=1        [5,6]
    //   y=0  [0,1]
    EXPECT_FALSE(stabbable({yDoor(0, 0, 1), yDoor(1, 5, 6), yDoor(2, 0, 1)}));
    EXPECT_TRUE(stabbable({yDoor(0, 0, 1), yDoor(1, 5, 6)}));
    EXPECT_TRUE(stabbable({yDoor(0, 0, 1), yDoor(1, 1, 2), yDoor(2, 2, 3)}));
    // The same zig-zag in z (doors stacked) and the aligned control case.
    EXPECT_FALSE(stabbable({yDoor(0, 0, 1, 0, 1), yDoor(1, 0, 1, 5, 6), yDoor(2, 0, 1, 0, 1)}));
    EXPECT_TRUE(stabbable({yDoor(0, 0, 1), yDoor(1, 0, 1), yDoor(2, 0, 1)}));
}

TEST(PortalStabbing, SequenceTurningBackIsRejected)
{
    // Through x = 1 towards +x, up through y = 1, then back through x = 0 towards -x.
    EXPECT_FALSE(stabbable({xDoor(1, 0, 1), portal(1, 1, 0, 1, 1, 2), xDoor(0, 1, 2, 0, 1, false)}));
    // Two doors of the same wall crossed in opposite directions.
    EXPECT_FALSE(stabbable({xDoor(0, 0, 1), xDoor(3, 0, 1), xDoor(2, 0, 1, 0, 1, false)}));
    EXPECT_FALSE(stabbable({xDoor(0, 0, 1), xDoor(0.5, 2, 3, 0, 1, false)}));
    // In one plane, a line lying in it touches both (touching counts as crossing).
    EXPECT_TRUE(stabbable({xDoor(0, 0, 1), xDoor(0, 2, 3, 0, 1, false)}));
    // Same direction but the second door is behind the first.
    EXPECT_FALSE(stabbable({xDoor(2, 0, 1), xDoor(1, 0, 1)}));
}

TEST(PortalStabbing, LShapedCorridorBlocksTheSightline)
{
    //  y=10      [8,10]
    //            |    |
    //  y=2 ------ [8,10]
    //  x=0 |  x=5 |
    //  y in [0,2] along x, then up along y
    const std::vector<OrientedPortal> threeDoors = {xDoor(0, 0, 2, 0, 3), xDoor(5, 0, 2, 0, 3), yDoor(2, 8, 10, 0, 3)};
    EXPECT_TRUE(stabbable(threeDoors)); // slope 0.2 from (0,0) reaches y = 2 at x = 10
    std::vector<OrientedPortal> fourDoors = threeDoors;
    fourDoors.push_back(yDoor(10, 8, 10, 0, 3));
    EXPECT_FALSE(stabbable(fourDoors));
}

TEST(PortalStabbing, DegenerateInputs)
{
    // A zero-width door between two aligned ones is still crossed...
    EXPECT_TRUE(stabbable({yDoor(0, 0, 1), yDoor(1, 0.5, 0.5), yDoor(2, 0, 1)}));
    // ...but it pins the line: through x = 0.5 at y = 1 from x in [0,1] at y = 0 gives x in [0,1] at y = 2.
    EXPECT_FALSE(stabbable({yDoor(0, 0, 1), yDoor(1, 0.5, 0.5), yDoor(2, 5, 6)}));
    // Zero width in both directions: a point.
    EXPECT_TRUE(stabbable({yDoor(0, 0, 1), portal(1, 1, 0.5, 0.5, 0.5, 0.5), yDoor(2, 0, 1)}));
    // An inverted (empty) portal lets nothing through; inverted within tolerance is a segment.
    EXPECT_FALSE(stabbable({yDoor(0, 0, 1), yDoor(1, 0.6, 0.4)}));
    EXPECT_TRUE(stabbable({yDoor(0, 0, 1), yDoor(1, 0.5 + 0.4 * Tolerance, 0.5), yDoor(2, 0, 1)}));
    // Coplanar consecutive doors sharing an edge: a line in their plane touches both.
    EXPECT_TRUE(stabbable({yDoor(0, 0, 1), yDoor(0, 1, 2)}));
}

TEST(PortalStabbing, LinesAlongTheDroppedAxisAreNotRejected)
{
    // Three doors of different axes meeting in the vertical line x = 1, y = 1: the only lines
    // crossing all three within tolerance are (near) that vertical line, which projects to a
    // point when z is dropped.
    const std::vector<OrientedPortal> meeting = {xDoor(1, 0, 1, 0, 1), portal(1, 1, 1, 2, 0, 1), xDoor(1, 1, 2, 1, 2)};
    EXPECT_TRUE(stabbable(meeting));
    // Vertical doors' edges (x-normal at x = 1 spanning y in [0,1], y-normal at y = 1 spanning
    // x in [1,2]) only touch at the point (1,1) in the xy projection.
    EXPECT_TRUE(stabbable({xDoor(1, 0, 1, 0, 1), yDoor(1, 1, 2, 5, 6)}));
}

TEST(PortalStabbing, RandomSequencesAroundLinesAreNeverRejected)
{
    RandomLines random(20240601);
    int rejected = 0, funnelMisses = 0, boxMisses = 0, cases = 0;
    for (int trial = 0; trial < 3000; ++trial)
    {
        const RandomLineCase c = random.make(2 + trial % 7, random.uniform(-5.0, 5.0));
        ++cases;
        // A zero tolerance still accepts: rounding is allowed for inside.
        if (!stabbable(c.portals) || !portalSequenceStabbable(c.portals.data(), c.portals.size(), 0.0))
        {
            ++rejected;
            ADD_FAILURE() << "trial " << trial << " rejected";
            continue;
        }
        const PortalFunnel funnel = portalFunnel(c.portals.data(), c.portals.size());
        for (int k = 0; k < 3; ++k)
        {
            const double lambda = c.parameters.back() + random.uniform(0.0, 10.0);
            const Vec3 beyond = c.origin + lambda * c.direction;
            for (const Plane& plane : funnel.planes)
                if (plane.distance(beyond) < -Tolerance)
                {
                    ++funnelMisses;
                    ADD_FAILURE() << "trial " << trial << " point beyond outside funnel by " << plane.distance(beyond);
                    break;
                }
            if (!boxMeetsFunnel(cubeAround(beyond, random.uniform(1e-3, 2.0)), funnel, Tolerance))
            {
                ++boxMisses;
                ADD_FAILURE() << "trial " << trial << " box beyond misses funnel";
            }
        }
    }
    EXPECT_EQ(cases, 3000);
    EXPECT_EQ(rejected, 0);
    EXPECT_EQ(funnelMisses, 0);
    EXPECT_EQ(boxMisses, 0);
}

TEST(PortalStabbing, IllConditionedSequencesFoundByStressRuns)
{
    // Long chains of 1e-3 portals around one line, found by a 200k-case stress run, where the
    // simplex (then pivoting on small elements) lost accuracy and reported too low an optimum
    // (first case: the Plücker LP; second: the funnel LP). Harris pivoting keeps them accurate,
    // and rejection rests on the LP's dual bound, which rounding cannot lower.
    const std::vector<OrientedPortal> pluckerCase = {
        portal(0, 5.1757530213548222, -0.81702165486498368, -0.81602165486498368, 2.7457450713090692,
               2.7509960901562835),
        portal(2, 5.1928804363630263, 5.3639692505617305, 5.3669830450663047, 0.24803388684873379, 0.28184236122315465),
        portal(1, 0.58657278357543507, 5.9536323920167016, 5.9879952431251748, 5.4017664712768028, 5.4729279693662534),
        portal(1, 0.58749114619967191, 5.9572234895894107, 6.0811795238801736, 5.22450664155736, 5.768375917516841),
        portal(1, 0.59137343175392276, 5.9661061758879921, 5.9781713177072753, 5.4236915917215702, 5.4266864333519829),
        portal(1, 2.2265853393438335, 9.6998571091397494, 9.7185667437376733, 5.7117432660189094, 5.7138576239134382),
        portal(2, 13.807278556269971, 5.9804124921805748, 6.0273906822552297, 3.6059646319022964, 4.0872084984391224),
        portal(2, 13.808943732247894, 6.0272049798674194, 6.0282049798674198, 4.0170895581666288, 4.0191805557263285)};
    EXPECT_TRUE(stabbable(pluckerCase));
    const std::vector<OrientedPortal> funnelCase = {
        portal(2, 1.2396105770794286, 2.2599456491650933, 2.262157753130468, 0.16937296829258902, 0.60207371508290453),
        portal(0, 2.2598329248521525, 0.4842683111887085, 0.48544095788085662, 1.2435394718615487, 1.2445394718615486,
               false),
        portal(1, -0.91599260793863535, 4.777918134951423, 4.8052678560999142, 0.57249416577492551, 0.57349416577492551,
               false),
        portal(2, 6.2021513156259367, -0.097756080914980531, -0.093657306851701705, -1.4704295277353254,
               -1.416056928473534),
        portal(1, -2.9253423090864725, 5.2799034718521467, 9.8900344890577117, -2.0671506683666738, 0.76547417734488699,
               false)};
    EXPECT_TRUE(stabbable(funnelCase));
}

TEST(PortalStabbing, RandomSequencesAtOtherScalesAndPlaces)
{
    // The same construction scaled by 1e-3 and 1e3 and moved far from the origin, with the
    // tolerance scaled alike: the normalised frame keeps the answers.
    RandomLines random(31337);
    const double scales[] = {1e-3, 1e3};
    const Vec3 offset(12345.0, -6789.0, 4242.0);
    int rejected = 0;
    for (int trial = 0; trial < 1000; ++trial)
    {
        const double scale = scales[trial % 2];
        RandomLineCase c = random.make(2 + trial % 7, random.uniform(-5.0, 5.0));
        for (OrientedPortal& p : c.portals)
        {
            const int axis = p.rect.axis;
            p.rect.coordinate = offset[axis] + scale * p.rect.coordinate;
            p.rect.uMin = offset[AxialRect::uAxis(axis)] + scale * p.rect.uMin;
            p.rect.uMax = offset[AxialRect::uAxis(axis)] + scale * p.rect.uMax;
            p.rect.vMin = offset[AxialRect::vAxis(axis)] + scale * p.rect.vMin;
            p.rect.vMax = offset[AxialRect::vAxis(axis)] + scale * p.rect.vMax;
        }
        if (!portalSequenceStabbable(c.portals.data(), c.portals.size(), Tolerance * scale))
        {
            ++rejected;
            ADD_FAILURE() << "trial " << trial << " rejected at scale " << scale;
        }
    }
    EXPECT_EQ(rejected, 0);
    // And the zig-zag is still rejected there.
    std::vector<OrientedPortal> zigZag = {yDoor(0, 0, 1), yDoor(1, 5, 6), yDoor(2, 0, 1)};
    for (OrientedPortal& p : zigZag)
    {
        p.rect.coordinate = offset.y + 1e3 * p.rect.coordinate;
        p.rect.uMin = offset.z + 1e3 * p.rect.uMin;
        p.rect.uMax = offset.z + 1e3 * p.rect.uMax;
        p.rect.vMin = offset.x + 1e3 * p.rect.vMin;
        p.rect.vMax = offset.x + 1e3 * p.rect.vMax;
    }
    EXPECT_FALSE(portalSequenceStabbable(zigZag.data(), zigZag.size(), Tolerance * 1e3));
}

TEST(PortalStabbing, RandomSightlinesAreNeverRejected)
{
    RandomLines random(777);
    int rejected = 0, boxRejected = 0;
    for (int trial = 0; trial < 2000; ++trial)
    {
        const int count = trial % 7; // 0..6 portals
        const RandomLineCase c = random.make(std::max(count, 1), random.uniform(1e-3, 3.0));
        const Vec3& eye = c.origin;
        std::vector<OrientedPortal> portals(c.portals.begin(), c.portals.begin() + count);
        // Frustum side planes through the eye keeping the ray (some with the ray on the boundary).
        std::vector<Plane> viewPlanes;
        for (int k = 0; k < 4; ++k)
        {
            Vec3 n = random.unitVector();
            if (glm::dot(n, c.direction) < 0.0)
                n = -n;
            if (random.uniform(0, 1) < 0.25)
                n = glm::normalize(n - glm::dot(n, c.direction) * c.direction);
            viewPlanes.push_back(Plane::fromPointNormal(eye, n));
        }
        const double tolerance = (trial % 2 == 0) ? Tolerance : 0.0;
        if (count > 0 && !eyeSeesThroughPortals(eye, portals.data(), portals.size(), viewPlanes, tolerance))
        {
            ++rejected;
            ADD_FAILURE() << "trial " << trial << " sightline rejected";
        }
        const double lastParameter = count > 0 ? c.parameters[static_cast<std::size_t>(count) - 1] : 0.0;
        const Vec3 later = eye + (lastParameter + random.uniform(1e-3, 10.0)) * c.direction;
        const Aabb box = cubeAround(later, random.uniform(0.0, 1.0));
        if (!eyeSeesBoxThroughPortals(eye, portals.data(), portals.size(), viewPlanes, box, tolerance))
        {
            ++boxRejected;
            ADD_FAILURE() << "trial " << trial << " box rejected";
        }
    }
    EXPECT_EQ(rejected, 0);
    EXPECT_EQ(boxRejected, 0);
}

TEST(PortalStabbing, FunnelExcludesBoxesBesideIt)
{
    // Doors x,z in [0,1] at y = 0 and y = 1: at y = 3 the lines through both reach x in [-2, 3].
    const std::vector<OrientedPortal> doors = {yDoor(0, 0, 1), yDoor(1, 0, 1)};
    const PortalFunnel funnel = portalFunnel(doors.data(), doors.size());
    EXPECT_TRUE(boxMeetsFunnel({Vec3(2.5, 2.9, 0.4), Vec3(2.6, 3.1, 0.6)}, funnel, Tolerance));
    EXPECT_TRUE(boxMeetsFunnel({Vec3(-2.5, 2.9, 0.4), Vec3(-1.9, 3.1, 0.6)}, funnel, Tolerance));
    EXPECT_FALSE(boxMeetsFunnel({Vec3(3.5, 2.9, 0.4), Vec3(4.0, 3.1, 0.6)}, funnel, Tolerance));
    EXPECT_FALSE(boxMeetsFunnel({Vec3(0.4, 2.9, 3.5), Vec3(0.6, 3.1, 4.0)}, funnel, Tolerance));
    // Behind the last door.
    EXPECT_FALSE(boxMeetsFunnel({Vec3(0.4, 0.2, 0.4), Vec3(0.6, 0.8, 0.6)}, funnel, Tolerance));
    // At y = 3 the funnel's section is the square x, z in [-2, 3]: a box reaching its corner
    // meets it, one just beside it does not.
    EXPECT_TRUE(boxMeetsFunnel({Vec3(2.9, 3.0, 2.9), Vec3(3.5, 3.0, 3.5)}, funnel, Tolerance));
    EXPECT_FALSE(boxMeetsFunnel({Vec3(3.01, 3.0, 2.0), Vec3(3.5, 3.0, 3.5)}, funnel, Tolerance));
    EXPECT_FALSE(boxMeetsFunnel(Aabb(), funnel, Tolerance));

    // Deterministic.
    const PortalFunnel again = portalFunnel(doors.data(), doors.size());
    ASSERT_EQ(again.planes.size(), funnel.planes.size());
    for (std::size_t i = 0; i < funnel.planes.size(); ++i)
    {
        EXPECT_EQ(again.planes[i].normal, funnel.planes[i].normal);
        EXPECT_EQ(again.planes[i].d, funnel.planes[i].d);
    }
}

TEST(PortalStabbing, EyeCasesThatMustBeRejected)
{
    const Vec3 eye(0.5, -1.0, 0.5);
    const std::vector<OrientedPortal> door = {yDoor(0, 0, 1)};
    // Looking away from the door.
    EXPECT_FALSE(eyeSeesThroughPortals(eye, door.data(), 1, {Plane::fromPointNormal(eye, Vec3(0, -1, 0))}, Tolerance));
    // A side plane keeping x >= 0.5 + 0.2 (y + 1) meets the door; x >= 0.5 + 2 (y + 1) does not.
    EXPECT_TRUE(eyeSeesThroughPortals(eye, door.data(), 1, {Plane::fromPointNormal(eye, Vec3(1, -0.2, 0))}, Tolerance));
    EXPECT_FALSE(eyeSeesThroughPortals(eye, door.data(), 1, {Plane::fromPointNormal(eye, Vec3(1, -2, 0))}, Tolerance));
    // The eye beyond the door's plane.
    EXPECT_FALSE(eyeSeesThroughPortals(Vec3(0.5, 0.5, 0.5), door.data(), 1, {}, Tolerance));
    // Through two doors offset so that the second is only seen from far to the left.
    const std::vector<OrientedPortal> two = {yDoor(0, 0, 1), yDoor(1, 3, 4)};
    EXPECT_FALSE(eyeSeesThroughPortals(eye, two.data(), 2, {}, Tolerance)); // needs x >= 2 at y=0
    EXPECT_TRUE(eyeSeesThroughPortals(Vec3(-3.0, -1.0, 0.5), two.data(), 2, {}, Tolerance));

    // A frustum looking along +y.
    const std::vector<Plane> frustum = {
        Plane::fromPointNormal(eye, Vec3(1, 1, 0)), Plane::fromPointNormal(eye, Vec3(-1, 1, 0)),
        Plane::fromPointNormal(eye, Vec3(0, 1, 1)), Plane::fromPointNormal(eye, Vec3(0, 1, -1))};
    const Aabb behindEye(Vec3(0, -5, 0), Vec3(1, -3, 1));
    const Aabb inFront(Vec3(0, 3, 0), Vec3(1, 5, 1));
    EXPECT_FALSE(eyeSeesBoxThroughPortals(eye, nullptr, 0, frustum, behindEye, Tolerance));
    EXPECT_TRUE(eyeSeesBoxThroughPortals(eye, nullptr, 0, frustum, inFront, Tolerance));
    EXPECT_TRUE(eyeSeesBoxThroughPortals(eye, nullptr, 0, {}, behindEye, Tolerance));
    EXPECT_FALSE(eyeSeesBoxThroughPortals(eye, door.data(), 1, {}, behindEye, Tolerance));
    EXPECT_TRUE(eyeSeesBoxThroughPortals(eye, door.data(), 1, frustum, inFront, Tolerance));
    // Beside the cone through the door: from (0.5,-1) through x in [0,1] at y = 0, at y = 4 the
    // cone spans x in [-2, 3].
    EXPECT_FALSE(
        eyeSeesBoxThroughPortals(eye, door.data(), 1, {}, {Vec3(3.5, 3.9, 0.4), Vec3(4, 4.1, 0.6)}, Tolerance));
    EXPECT_TRUE(
        eyeSeesBoxThroughPortals(eye, door.data(), 1, {}, {Vec3(2.5, 3.9, 0.4), Vec3(2.9, 4.1, 0.6)}, Tolerance));
    // Between the door and the eye: in the cone but not beyond the door.
    EXPECT_FALSE(
        eyeSeesBoxThroughPortals(eye, door.data(), 1, {}, {Vec3(0.4, -0.5, 0.4), Vec3(0.6, -0.4, 0.6)}, Tolerance));
}

TEST(PortalStabbing, EyeOnAPortalPlaneOrEdgeLine)
{
    const std::vector<OrientedPortal> doors = {yDoor(0, 0, 1), yDoor(1, 0, 1)};
    const Aabb far(Vec3(0.4, 5, 0.4), Vec3(0.6, 6, 0.6));
    // On the first door's plane, inside it.
    EXPECT_TRUE(eyeSeesThroughPortals(Vec3(0.5, 0, 0.5), doors.data(), 2, {}, Tolerance));
    EXPECT_TRUE(eyeSeesBoxThroughPortals(Vec3(0.5, 0, 0.5), doors.data(), 2, {}, far, Tolerance));
    // On a corner of the first door (and so on two of its edge lines).
    EXPECT_TRUE(eyeSeesThroughPortals(Vec3(0, 0, 0), doors.data(), 2, {}, Tolerance));
    EXPECT_TRUE(eyeSeesBoxThroughPortals(Vec3(0, 0, 0), doors.data(), 2, {}, far, Tolerance));
    // On the line of the first door's bottom edge, beside the door: the cone is degenerate and
    // must not reject.
    EXPECT_TRUE(eyeSeesThroughPortals(Vec3(2, 0, 0), doors.data(), 2, {}, Tolerance));
    // On the first door's side edge line x = 1, y = 0, below the door: the box lies in the cone
    // through the second door (x in [-4, 1], z in [8, 13] at y = 5).
    EXPECT_TRUE(eyeSeesBoxThroughPortals(Vec3(1, 0, -2), doors.data(), 2, {}, {Vec3(0.5, 5, 9), Vec3(0.7, 5.2, 9.2)},
                                         Tolerance));
    EXPECT_FALSE(eyeSeesBoxThroughPortals(Vec3(1, 0, -2), doors.data(), 2, {}, {Vec3(0.5, 5, 3), Vec3(0.7, 5.2, 3.2)},
                                          Tolerance));
    // On the plane of the only (last) door, inside it, and beside it.
    EXPECT_TRUE(eyeSeesThroughPortals(Vec3(0.5, 0, 0.5), doors.data(), 1, {}, Tolerance));
    EXPECT_TRUE(eyeSeesBoxThroughPortals(Vec3(3, 0, 0.5), doors.data(), 1, {}, far, Tolerance));
}

TEST(PortalStabbing, LoosenessAgainstBruteForceLines)
{
    // Random sequences of 3..6 doors along a wandering path (not built around a line). A line
    // through random points of the first and last door that crosses the others in order and
    // direction proves the sequence stabbable: every such sequence must be accepted.
    std::mt19937 rng(99);
    auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    int sequences = 0, accepted = 0, bruteStabbed = 0, missed = 0;
    for (int trial = 0; trial < 600; ++trial)
    {
        const int count = 3 + trial % 4;
        std::vector<OrientedPortal> portals;
        Vec3 at(0.0);
        for (int i = 0; i < count; ++i)
        {
            const int axis = (rng() % 3 == 0) ? static_cast<int>(rng() % 3) : 1; // mostly along +y
            at[axis] += uniform(0.5, 3.0);
            const double uSize = uniform(0.3, 3.0), vSize = uniform(0.3, 3.0);
            const double u = at[AxialRect::uAxis(axis)] + uniform(-1.5, 1.5);
            const double v = at[AxialRect::vAxis(axis)] + uniform(-1.5, 1.5);
            portals.push_back(portal(axis, at[axis], u - uSize / 2, u + uSize / 2, v - vSize / 2, v + vSize / 2));
        }
        ++sequences;
        const bool answer = stabbable(portals);
        accepted += answer ? 1 : 0;

        auto pointIn = [&](const AxialRect& r)
        {
            Vec3 p(0.0);
            p[r.axis] = r.coordinate;
            p[AxialRect::uAxis(r.axis)] = uniform(r.uMin, r.uMax);
            p[AxialRect::vAxis(r.axis)] = uniform(r.vMin, r.vMax);
            return p;
        };
        bool found = false;
        for (int sample = 0; sample < 3000 && !found; ++sample)
        {
            const Vec3 a = pointIn(portals.front().rect);
            const Vec3 b = pointIn(portals.back().rect);
            const Vec3 d = b - a;
            bool ok = d[portals.front().rect.axis] > 0.0 && d[portals.back().rect.axis] > 0.0;
            double previous = 0.0;
            for (int i = 1; ok && i + 1 < count; ++i)
            {
                const AxialRect& r = portals[static_cast<std::size_t>(i)].rect;
                if (!(d[r.axis] > 0.0))
                {
                    ok = false;
                    break;
                }
                const double s = (r.coordinate - a[r.axis]) / d[r.axis];
                const Vec3 x = a + s * d;
                const double u = x[AxialRect::uAxis(r.axis)], v = x[AxialRect::vAxis(r.axis)];
                ok = s >= previous && s <= 1.0 && u >= r.uMin && u <= r.uMax && v >= r.vMin && v <= r.vMax;
                previous = s;
            }
            found = ok;
        }
        if (found)
        {
            ++bruteStabbed;
            if (!answer)
            {
                ++missed;
                ADD_FAILURE() << "trial " << trial << ": a line exists but the sequence was rejected";
            }
        }
    }
    std::printf("[ looseness ] %d random sequences: brute force found a line through %d (%.3f), test accepts %d "
                "(%.3f); accepted without a found line: %d\n",
                sequences, bruteStabbed, double(bruteStabbed) / sequences, accepted, double(accepted) / sequences,
                accepted - bruteStabbed);
    EXPECT_EQ(missed, 0);
    EXPECT_GT(bruteStabbed, 30);    // the generator makes enough stabbable sequences to mean something
    EXPECT_LT(accepted, sequences); // and the test rejects some
    // Tightness with this seed: 5 accepted without a brute-force line (23 before the funnel check).
    EXPECT_LE(accepted - bruteStabbed, 10);
}

TEST(PortalStabbing, QueriesAllocateNothingOnceWarm)
{
    const std::vector<OrientedPortal> doors = {yDoor(0, 0, 1), xDoor(2, 1, 2), yDoor(4, 2, 4), yDoor(6, 3, 5)};
    const PortalFunnel funnel = portalFunnel(doors.data(), doors.size());
    const std::vector<Plane> view = {Plane::fromPointNormal(Vec3(0.5, -1, 0.5), Vec3(1, 1, 0)),
                                     Plane::fromPointNormal(Vec3(0.5, -1, 0.5), Vec3(-1, 1, 0))};
    const Aabb box(Vec3(3, 7, 0), Vec3(4, 8, 1));
    auto runAll = [&]
    {
        int answers = 0;
        answers += stabbable(doors) ? 1 : 0;
        answers += boxMeetsFunnel(box, funnel, Tolerance) ? 1 : 0;
        answers += eyeSeesThroughPortals(Vec3(0.5, -1, 0.5), doors.data(), doors.size(), view, Tolerance) ? 1 : 0;
        answers +=
            eyeSeesBoxThroughPortals(Vec3(0.5, -1, 0.5), doors.data(), doors.size(), view, box, Tolerance) ? 1 : 0;
        return answers;
    };
    const int warm = runAll();
    const std::size_t before = osgVis::test::allocationCount();
    int same = 0;
    for (int i = 0; i < 100; ++i)
        same += runAll() == warm ? 1 : 0;
    EXPECT_EQ(osgVis::test::allocationCount(), before);
    EXPECT_EQ(same, 100);
}

TEST(PortalStabbing, ThreadsGetTheSameAnswers)
{
    // Scratch buffers are per thread: concurrent queries answer as a single thread does.
    RandomLines random(5);
    std::vector<std::vector<OrientedPortal>> sequences;
    for (int i = 0; i < 200; ++i)
    {
        std::vector<OrientedPortal> portals = random.make(3 + i % 4, 0.0).portals;
        portals.back().rect.uMin += 0.5 * (i % 3); // some no longer stabbable
        sequences.push_back(portals);
    }
    std::vector<char> expected;
    int accepted = 0;
    for (const auto& s : sequences)
    {
        expected.push_back(stabbable(s) ? 1 : 0);
        accepted += expected.back();
    }
    EXPECT_GT(accepted, 0);
    EXPECT_LT(accepted, 200);
    std::vector<int> mismatches(4, 0);
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t)
        threads.emplace_back(
            [&, t]
            {
                for (int rep = 0; rep < 5; ++rep)
                    for (std::size_t i = 0; i < sequences.size(); ++i)
                        mismatches[static_cast<std::size_t>(t)] += (stabbable(sequences[i]) ? 1 : 0) != expected[i];
            });
    for (std::thread& thread : threads)
        thread.join();
    for (int m : mismatches)
        EXPECT_EQ(m, 0);
}
