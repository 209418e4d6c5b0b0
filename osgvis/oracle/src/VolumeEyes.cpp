// SPDX-License-Identifier: MIT
#include <osgVis/oracle/VolumeEyes.h>

#include <array>
#include <random>
#include <set>
#include <stdexcept>

namespace osgVis::oracle
{
std::vector<osg::Vec3d> volumeEyes(const osg::BoundingBoxd& box, unsigned interior, std::uint32_t seed)
{
    if (!box.valid())
        throw std::invalid_argument("osgVis volume eyes: invalid box");
    std::vector<osg::Vec3d> eyes;
    std::set<std::array<double, 3>> listed;
    const auto add = [&](const osg::Vec3d& p)
    {
        if (listed.insert({p.x(), p.y(), p.z()}).second)
            eyes.push_back(p);
    };
    for (unsigned c = 0; c < 8; ++c)
        add(box.corner(c));
    const osg::Vec3d centre = box.center();
    for (int axis = 0; axis < 3; ++axis)
        for (double side : {box._min[axis], box._max[axis]})
        {
            osg::Vec3d p = centre;
            p[axis] = side;
            add(p);
        }
    // std::uniform_real_distribution is not the same everywhere; the top 53 bits of a 64-bit draw are.
    std::mt19937_64 engine(seed);
    const auto unit = [&] { return double(engine() >> 11) * (1.0 / 9007199254740992.0); };
    for (unsigned i = 0; i < interior; ++i)
    {
        osg::Vec3d p;
        for (int axis = 0; axis < 3; ++axis)
            p[axis] = box._min[axis] + (box._max[axis] - box._min[axis]) * unit();
        add(p);
    }
    return eyes;
}
} // namespace osgVis::oracle
