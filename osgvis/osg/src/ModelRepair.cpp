// SPDX-License-Identifier: MIT
#include <osgVis/ModelRepair>

#include <osgVis/Q3Bsp>

#include <osg/Drawable>
#include <osg/Geode>
#include <osg/Geometry>
#include <osg/Notify>
#include <osg/NodeVisitor>
#include <osgDB/FileNameUtils>

#include <algorithm>
#include <string>

namespace osgVis
{
namespace
{
class PolygonModeRemover : public osg::NodeVisitor
{
public:
    PolygonModeRemover() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
    unsigned removed = 0;

    void apply(osg::Node& node) override
    {
        clean(node.getStateSet());
        traverse(node);
    }
    void apply(osg::Drawable& drawable) override { clean(drawable.getStateSet()); }

private:
    void clean(osg::StateSet* stateSet)
    {
        if (stateSet && stateSet->getAttribute(osg::StateAttribute::POLYGONMODE))
        {
            stateSet->removeAttribute(osg::StateAttribute::POLYGONMODE);
            ++removed;
        }
    }
};

// Polygon faces drawn with q3map2's own triangles instead of the plugin's fan.
unsigned refanPolygonFaces(osg::Node& model, const std::string& path)
{
    Q3Bsp level;
    try
    {
        level = Q3Bsp::read(path);
    }
    catch (const std::exception& e)
    {
        OSG_WARN << "osgVis: " << e.what() << "; its polygon faces stay as the bsp plugin drew them" << std::endl;
        return 0;
    }
    const std::vector<int>& faces = level.drawableFaces();
    osg::Geode* geode = level.pluginGeode(model);
    if (!geode)
        return 0; // not the plugin's layout (a Valve map, another version): left alone
    unsigned repaired = 0;
    for (std::size_t k = 0; k < faces.size(); ++k)
    {
        osg::Geometry* geometry = geode->getDrawable(unsigned(k))->asGeometry();
        if (!geometry || !level.isPolygonFace(faces[k]) || geometry->getNumPrimitiveSets() != 1)
            continue;
        const osg::PrimitiveSet* fan = geometry->getPrimitiveSet(0);
        if (fan->getMode() != osg::PrimitiveSet::TRIANGLE_FAN)
            continue;
        const std::vector<std::uint32_t> triangles = level.faceTriangles(faces[k]);
        const osg::Array* vertices = geometry->getVertexArray();
        if (triangles.empty() || !vertices ||
            *std::max_element(triangles.begin(), triangles.end()) >= vertices->getNumElements())
            continue;
        geometry->setPrimitiveSet(0, new osg::DrawElementsUInt(osg::PrimitiveSet::TRIANGLES, triangles.begin(), triangles.end()));
        geometry->dirtyBound();
        ++repaired;
    }
    return repaired;
}
} // namespace

std::string repairLoadedModel(osg::Node& model, const std::string& path)
{
    if (osgDB::getLowerCaseFileExtension(path) != "bsp")
        return {};
    PolygonModeRemover remover;
    model.accept(remover);
    const unsigned refanned = refanPolygonFaces(model, path);
    std::string said;
    if (remover.removed)
        said = "removed the wireframe PolygonMode OSG's bsp plugin put on " + std::to_string(remover.removed) + " faces";
    if (refanned)
        said += std::string(said.empty() ? "" : "; ") + "drew " + std::to_string(refanned) +
                " polygon faces with the level's own triangles, not the plugin's fans";
    return said;
}
} // namespace osgVis
