// SPDX-License-Identifier: MIT
#include <osgVis/SceneExtractor>

#include <osgVis/Cell>
#include <osgVis/Occluder>
#include <osgVis/Portal>
#include <osgVis/VisibilityGroup>

#include "CullingContext.h"
#include "CullTree.h"
#include "DrawableGeometry.h"
#include "Extraction.h"
#include "OccluderEligibility.h"

#include <osg/AutoTransform>
#include <osg/Billboard>
#include <osg/Camera>
#include <osg/Geode>
#include <osg/Geometry>
#include <osg/MatrixTransform>
#include <osg/NodeVisitor>
#include <osg/Notify>
#include <osg/PagedLOD>
#include <osg/PositionAttitudeTransform>
#include <osg/PrimitiveSet>
#include <osg/Projection>
#include <osg/ProxyNode>
#include <osg/TriangleFunctor>
#include <osg/ValueObject>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <typeinfo>
#include <unordered_map>

namespace osgVis
{
ExtractedScene::~ExtractedScene() = default;

core::ObjectId ExtractedScene::find(const osg::Node* d, const osg::NodePath& path, std::size_t pathBegin) const
{
    const auto found = _idsByNode.find(d);
    if (found == _idsByNode.end() || pathBegin > path.size())
        return core::InvalidObject;
    const std::size_t length = path.size() - pathBegin;
    for (core::ObjectId id : found->second)
    {
        const osg::NodePath& refPath = refs[id].path;
        if (refPath.size() == length && std::equal(refPath.begin(), refPath.end(), path.begin() + pathBegin))
            return id;
    }
    return core::InvalidObject;
}

const std::vector<core::ObjectId>& ExtractedScene::idsOf(const osg::Node* d) const
{
    static const std::vector<core::ObjectId> none;
    const auto found = _idsByNode.find(d);
    return found == _idsByNode.end() ? none : found->second;
}

void ExtractedScene::indexObject(core::ObjectId id)
{
    if (removed(id))
        return;
    _idsByNode[refs[id].node()].push_back(id);
}

bool ExtractedScene::pagedNodesChanged() const
{
    for (const PagedNodeRecord& record : pagedNodes)
        if (refs[record.placeholder].paged->getNumChildren() != record.children)
            return true;
    return false;
}

// Node types whose cull traversal draws exactly their drawables, nothing else (see ChildRange::closed).
bool plainNodeType(const osg::Node& node)
{
    const std::type_info& t = typeid(node);
    return t == typeid(osg::Group) || t == typeid(osg::Geode) || t == typeid(osg::MatrixTransform) ||
           t == typeid(osg::PositionAttitudeTransform) || t == typeid(Occluder) || t == typeid(Cell) ||
           t == typeid(Portal);
}

bool plainCullCallback(const osg::Drawable& drawable)
{
    const osg::Callback* cb = drawable.getCullCallback();
    if (!cb)
        return true;
    const auto* own = dynamic_cast<const VisibilityCullCallback*>(cb);
    return own && !own->getChained();
}

namespace
{
bool transparentState(const osg::StateSet* ss)
{
    return ss && ((ss->getMode(GL_BLEND) & osg::StateAttribute::ON) ||
                  ss->getRenderingHint() == osg::StateSet::TRANSPARENT_BIN);
}

bool isOsgVisGroup(const osg::Node& node)
{
    return dynamic_cast<const VisibilityGroup*>(&node) != nullptr;
}

} // namespace

namespace
{
bool sphereStated(const osg::Group& node)
{
    // note: PagedLOD and ProxyNode default to USER_DEFINED_CENTER with radius -1, which OSG reads as
    // "from the children"
    if (const auto* paged = dynamic_cast<const osg::PagedLOD*>(&node))
        return paged->getCenterMode() != osg::LOD::USE_BOUNDING_SPHERE_CENTER && paged->getRadius() >= 0;
    const auto* proxy = dynamic_cast<const osg::ProxyNode*>(&node);
    return proxy && proxy->getCenterMode() != osg::ProxyNode::USE_BOUNDING_SPHERE_CENTER && proxy->getRadius() >= 0;
}

// The box the node's user values state (PagedBoundsMin/Max), in its local frame.
bool boxStated(const osg::Group& node, osg::BoundingBoxd& box)
{
    osg::Vec3d lo, hi;
    if (!node.getUserValue(PagedBoundsMin, lo) || !node.getUserValue(PagedBoundsMax, hi))
        return false;
    box = osg::BoundingBoxd(lo, hi);
    return box.valid();
}
} // namespace

bool boundStated(const osg::Group& node)
{
    osg::BoundingBoxd box;
    return sphereStated(node) || boxStated(node, box);
}

unsigned pagedFileCount(const osg::Group& node)
{
    if (const auto* paged = dynamic_cast<const osg::PagedLOD*>(&node))
        return paged->getNumFileNames();
    const auto* proxy = dynamic_cast<const osg::ProxyNode*>(&node);
    return proxy ? proxy->getNumFileNames() : 0;
}

bool boundCoversAllChildren(const osg::Group& node)
{
    return boundStated(node) || node.getNumChildren() >= pagedFileCount(node);
}

std::string tileFile(const osg::Group& node, unsigned child)
{
    if (const auto* paged = dynamic_cast<const osg::PagedLOD*>(&node))
        return child < paged->getNumFileNames() ? paged->getDatabasePath() + paged->getFileName(child) : "";
    const auto* proxy = dynamic_cast<const osg::ProxyNode*>(&node);
    return proxy && child < proxy->getNumFileNames() ? proxy->getDatabasePath() + proxy->getFileName(child) : "";
}

void checkWithinStatedBound(ExtractedScene& out, core::ObjectId placeholder, std::size_t depth, core::ObjectId from)
{
    // note: a loaded tile's geometry must lie within the stated bound, or a hidden placeholder would
    // skip visible geometry; one that does not keeps its node always traversed.
    const osg::Group& node = *out.refs[placeholder].paged;
    core::SceneObject& stated = out.scene.objects[placeholder];
    if (!boundCoversAllChildren(node) || stated.bounds.empty())
        return; // always visible already, and nothing stated to exceed
    const double slack = 1e-6 * (1.0 + glm::length(stated.bounds.extent()));
    const core::Aabb allowed(stated.bounds.min - core::Vec3(slack), stated.bounds.max + core::Vec3(slack));
    std::vector<bool> oversized(node.getNumChildren(), false);
    const auto childOf = [&](core::ObjectId id)
    {
        const osg::NodePath& path = out.refs[id].path;
        return path.size() > depth + 1 ? node.getChildIndex(path[depth + 1]) : 0u;
    };
    for (core::ObjectId id = from; id < out.scene.objects.size(); ++id)
    {
        const core::Aabb& box = out.scene.objects[id].bounds;
        if (box.empty() || (glm::all(glm::greaterThanEqual(box.min, allowed.min)) &&
                            glm::all(glm::lessThanEqual(box.max, allowed.max))))
            continue;
        stated.flags |= core::OBJECT_ALWAYS_VISIBLE;
        const unsigned child = childOf(id);
        if (child < oversized.size() && !oversized[child])
        {
            oversized[child] = true;
            out.oversizedTiles.push_back(tileFile(node, child) + " ('" + node.getName() + "')");
        }
    }
    // note: OSG culls the node by the bound it states, so such a tile's geometry outside it may go
    // undrawn: none of the tile may occlude.
    for (core::ObjectId id = from; id < out.scene.objects.size(); ++id)
        if (childOf(id) < oversized.size() && oversized[childOf(id)])
            out.scene.objects[id].flags |= core::OBJECT_NO_AUTO_OCCLUDER;
}

namespace
{
class Extractor : public osg::NodeVisitor
{
public:
    Extractor(ExtractedScene& out, const ExtractionOptions& options)
        : osg::NodeVisitor(TRAVERSE_ACTIVE_CHILDREN), _out(out), _options(options)
    {
    }

    void run(osg::Node& root)
    {
        _root = &root;
        root.accept(*this);
        resolvePortals();
    }

    // Extracts `child` and its subtree, appended to the scene, as a full extraction from
    // `prefix.front()` would reach it through `prefix` (root .. child's parent).
    void runBelow(const osg::NodePath& prefix, osg::Node& child)
    {
        _root = prefix.front();
        for (osg::Node* node : prefix)
        {
            pushOntoNodePath(node);
            _unpredictableDepth += placedOnlyAtCull(*node);
            _occluderDepth += dynamic_cast<Occluder*>(node) != nullptr;
        }
        child.accept(*this);
        for (std::size_t i = 0; i < prefix.size(); ++i)
            popFromNodePath();
        resolvePortals();
    }

    void apply(osg::Node& node) override { visit(node, placedOnlyAtCull(node)); }
    void apply(osg::Group& node) override { visit(node, placedOnlyAtCull(node)); }
    void apply(osg::Geode& node) override { visit(node, placedOnlyAtCull(node)); }
    void apply(osg::Billboard& node) override { visit(node, placedOnlyAtCull(node)); }
    void apply(osg::Projection& node) override { visit(node, placedOnlyAtCull(node)); }
    void apply(osg::Camera& node) override { visit(node, placedOnlyAtCull(node)); }
    void apply(osg::AutoTransform& node) override { visit(node, placedOnlyAtCull(node)); }
    void apply(osg::Transform& node) override { visit(node, placedOnlyAtCull(node)); }
    void apply(osg::PagedLOD& node) override { visitPaged(node); }
    void apply(osg::ProxyNode& node) override { visitPaged(node); }

    void apply(osg::Drawable& drawable) override
    {
        if (drawable.getCullCallback() && !plainCullCallback(drawable))
            _closed = false;
        addObject(drawable);
    }

private:
    // The cull traversal places this node's subtree in a way extraction cannot know: screen-aligned,
    // in an absolute frame, under its own projection or camera, or by a matrix a Transform of a type
    // the kit does not know computes from the cull visitor (an eye-following sky). OSG never culls a
    // culling-inactive node by its bound: neither may a module.
    bool placedOnlyAtCull(const osg::Node& node) const
    {
        if (!node.getCullingActive())
            return true;
        if (dynamic_cast<const osg::Billboard*>(&node) || dynamic_cast<const osg::Projection*>(&node) ||
            dynamic_cast<const osg::AutoTransform*>(&node))
            return true;
        if (dynamic_cast<const osg::Camera*>(&node))
            return &node != _root;
        const osg::Transform* transform = node.asTransform();
        if (!transform)
            return false;
        return transform->getReferenceFrame() != osg::Transform::RELATIVE_RF ||
               (!transform->asMatrixTransform() && !transform->asPositionAttitudeTransform());
    }

    // `unpredictable`: the cull traversal places this node's subtree in a way extraction cannot know
    // (screen-aligned, absolute frame, own projection), so its objects must never be culled.
    void visit(osg::Node& node, bool unpredictable)
    {
        if (!plainNodeType(node) || node.getCullCallback())
            _closed = false;
        const bool isOccluder = dynamic_cast<Occluder*>(&node) != nullptr;
        if (unpredictable)
            ++_unpredictableDepth;
        if (isOccluder)
            ++_occluderDepth;
        if (auto* occluder = dynamic_cast<Occluder*>(&node))
            addOccluderPolygons(*occluder);
        else if (auto* cell = dynamic_cast<Cell*>(&node))
            addCell(*cell);
        else if (auto* portal = dynamic_cast<Portal*>(&node))
            _portals.push_back({portal, localToRoot()});

        osg::Group* group = node.asGroup();
        if (&node == _root && group &&
            (typeid(node) == typeid(osg::Group) || isOsgVisGroup(node) || plainNodeType(node)))
            traverseRootChildren(*group);
        else
        {
            if (group)
                for (unsigned i = 0; i < group->getNumChildren(); ++i)
                    if (!validNodeMask(*group->getChild(i)))
                        _closed = false; // a disabled child may be enabled later
            traverse(node);
        }

        if (isOccluder)
            --_occluderDepth;
        if (unpredictable)
            --_unpredictableDepth;
    }

    // A paged node: its placeholder first, then its loaded children as usual.
    void visitPaged(osg::Group& node)
    {
        const core::ObjectId placeholder = addPlaceholder(node, boundCoversAllChildren(node));
        const std::size_t depth = _nodePath.size() - 1; // the node's index in its objects' paths
        visit(node, false);
        checkWithinStatedBound(_out, placeholder, depth, placeholder + 1);
    }

    core::ObjectId addPlaceholder(osg::Group& node, bool statedForAll)
    {
        std::uint32_t flags = core::OBJECT_NONE;
        // In the node's frame: the sphere's cube, cut down to a stated box where there is one (the
        // geometry must lie in both).
        osg::BoundingBoxd local;
        const osg::BoundingSphere& sphere = node.getBound();
        if (sphere.valid())
        {
            const osg::Vec3d r(sphere.radius(), sphere.radius(), sphere.radius());
            local = osg::BoundingBoxd(osg::Vec3d(sphere.center()) - r, osg::Vec3d(sphere.center()) + r);
        }
        osg::BoundingBoxd stated;
        if (boxStated(node, stated))
            local = sphereStated(node) && local.valid() ? local.intersect(stated) : stated;
        BoundsAccumulator bounds(localToRoot());
        if (local.valid())
            for (unsigned corner = 0; corner < 8; ++corner)
                bounds.add(local.corner(corner));
        if (!local.valid() || !statedForAll || bounds.nonFinite || _unpredictableDepth > 0)
            flags |= core::OBJECT_ALWAYS_VISIBLE;
        const core::ObjectId id = _out.scene.addObject(bounds.bounds, 0, flags, node.getName());
        _out.scene.objects[id].firstTriangle = static_cast<std::uint32_t>(_out.scene.triangles.size());
        ObjectRef ref{nullptr, _nodePath, localToRoot(), nullptr, 0, &node};
        _out.refs.push_back(std::move(ref));
        _out.indexObject(id);
        PagedNodeRecord record{id, node.getNumChildren(), {}};
        for (unsigned child = 0; child < node.getNumChildren(); ++child)
            record.childNodes.push_back(node.getChild(child));
        _out.pagedNodes.push_back(std::move(record));
        return id;
    }

    // Visits the root's children one by one to record which ids each of them holds.
    void traverseRootChildren(osg::Group& root)
    {
        _out.childRanges.resize(root.getNumChildren());
        for (unsigned i = 0; i < root.getNumChildren(); ++i)
        {
            ChildRange& range = _out.childRanges[i];
            range.first = static_cast<core::ObjectId>(_out.scene.objects.size());
            osg::Node* child = root.getChild(i);
            _closed = validNodeMask(*child);
            if (_closed)
                child->accept(*this);
            range.end = static_cast<core::ObjectId>(_out.scene.objects.size());
            range.closed = _closed;
        }
    }

    osg::Matrixd localToRoot() const { return osg::computeLocalToWorld(_nodePath); }

    static bool mayOcclude(std::uint32_t flags)
    {
        constexpr std::uint32_t never = core::OBJECT_DYNAMIC | core::OBJECT_TRANSPARENT | core::OBJECT_ALWAYS_VISIBLE;
        return !(flags & never) && (!(flags & core::OBJECT_NO_AUTO_OCCLUDER) || (flags & core::OBJECT_OCCLUDER));
    }

    // The masks a view's traversal mask must meet to draw what lies at the end of the current path.
    void noteOccluderMasks()
    {
        std::vector<osg::Node::NodeMask>& masks = _out.occluderMasks;
        for (const osg::Node* node : _nodePath)
        {
            const osg::Node::NodeMask mask = node->getNodeMask();
            if (mask != ~osg::Node::NodeMask(0) && std::find(masks.begin(), masks.end(), mask) == masks.end())
                masks.push_back(mask);
        }
    }

    void addObject(osg::Drawable& drawable)
    {
        ObjectRef ref{&drawable, _nodePath, localToRoot(), nullptr, 0, nullptr};

        std::uint32_t flags = core::OBJECT_NONE;
        if (_unpredictableDepth > 0 || placedOnlyAtCull(drawable))
            flags |= core::OBJECT_ALWAYS_VISIBLE;
        if (_occluderDepth > 0)
            flags |= core::OBJECT_OCCLUDER;
        for (const osg::Node* n : _nodePath)
        {
            if (transparentState(n->getStateSet()))
                flags |= core::OBJECT_TRANSPARENT;
            if (n->getDataVariance() == osg::Object::DYNAMIC)
                flags |= core::OBJECT_DYNAMIC;
        }

        const OccluderEligibility eligibility = occluderEligibility(_nodePath);
        flags |= eligibility.flags;
        if (hasSlivers(drawable))
            flags |= core::OBJECT_SLIVERS;
        if (mayOcclude(flags))
            noteOccluderMasks();

        if (const ClusterLayout* layout = layoutFor(drawable))
            if (addClusters(drawable, ref, flags, *layout, eligibility.clockwiseFront))
                return;

        const DrawablePlacement placed = placeDrawable(drawable, ref.world, eligibility.clockwiseFront,
                                                       _options.keepTriangles ? &_out.scene.triangles : nullptr);
        if (placed.nonFinite)
            flags |= core::OBJECT_ALWAYS_VISIBLE;
        const auto firstTriangle = static_cast<std::uint32_t>(_out.scene.triangles.size()) - placed.stored;

        const core::ObjectId id = _out.scene.addObject(placed.bounds, placed.counted, flags, drawable.getName());
        core::SceneObject& object = _out.scene.objects[id];
        object.firstTriangle = firstTriangle;
        if (_options.keepTriangles)
            object.triangleCount = placed.stored;
        _out.refs.push_back(std::move(ref));
        _out.indexObject(id);
    }

    // The drawable's cluster layout (built once per drawable, shared by its instances), or null when it
    // stays whole.
    const ClusterLayout* layoutFor(osg::Drawable& drawable)
    {
        if (_options.clusterThreshold == 0 || _options.clusterTriangles == 0)
            return nullptr;
        const auto found = _layouts.find(&drawable);
        if (found != _layouts.end())
            return found->second.get();
        osg::ref_ptr<ClusterLayout> layout;
        const osg::Geometry* geometry = drawable.asGeometry();
        // note: a user's draw callback draws what it likes, and an explicit or computed bound may be
        // larger than the vertices (shader displacement): such drawables stay one object.
        if (geometry && !drawable.getDrawCallback() && !drawable.getInitialBound().valid() &&
            !drawable.getComputeBoundingBoxCallback())
        {
            TriangleCollector counter;
            osg::TriangleFunctor<TriangleCollector> functor;
            static_cast<TriangleCollector&>(functor) = counter;
            drawable.accept(functor);
            const std::uint32_t count = static_cast<const TriangleCollector&>(functor).count;
            if (count >= _options.clusterThreshold)
            {
                layout = ClusterLayout::build(*geometry, _options.clusterTriangles);
                // note: the clusters must hold exactly the triangles OSG's functor (and the oracle)
                // sees, or cluster-of-triangle numbering would not match
                if (layout && layout->triangleCount() != count)
                    layout = nullptr;
            }
        }
        if (layout)
            ++_out.clusteredDrawables;
        return (_layouts[&drawable] = layout).get();
    }

    // One object per cluster; false (nothing added) when a vertex is not finite in the root frame.
    bool addClusters(osg::Drawable& drawable, const ObjectRef& ref, std::uint32_t flags, const ClusterLayout& layout,
                     bool clockwiseFront)
    {
        const osg::Array* array = drawable.asGeometry()->getVertexArray();
        const auto* v3 = dynamic_cast<const osg::Vec3Array*>(array);
        const auto* v3d = dynamic_cast<const osg::Vec3dArray*>(array);
        const auto local = [&](GLuint i) { return v3 ? osg::Vec3d((*v3)[i]) : (*v3d)[i]; };
        const osg::DrawElementsUInt& indices = layout.indices();
        std::vector<core::Aabb> bounds(layout.size());
        std::vector<core::Triangle> triangles;
        if (_options.keepTriangles)
            triangles.reserve(layout.triangleCount());
        for (std::size_t c = 0; c < layout.size(); ++c)
        {
            const ClusterLayout::Cluster& cluster = layout.clusters()[c];
            for (std::uint32_t i = cluster.firstIndex; i < cluster.firstIndex + cluster.indexCount; i += 3)
            {
                osg::Vec3d w[3];
                for (int k = 0; k < 3; ++k)
                {
                    w[k] = local(indices[i + k]) * ref.world;
                    if (!finite(w[k]))
                        return false;
                    bounds[c].expand(toCore(w[k]));
                }
                if (clockwiseFront)
                    std::swap(w[1], w[2]);
                if (_options.keepTriangles)
                    triangles.push_back({core::Vec3f(w[0].x(), w[0].y(), w[0].z()),
                                         core::Vec3f(w[1].x(), w[1].y(), w[1].z()),
                                         core::Vec3f(w[2].x(), w[2].y(), w[2].z())});
            }
        }
        const auto firstId = static_cast<core::ObjectId>(_out.scene.objects.size());
        std::uint32_t firstTriangle = static_cast<std::uint32_t>(_out.scene.triangles.size());
        _out.scene.triangles.insert(_out.scene.triangles.end(), triangles.begin(), triangles.end());
        for (std::size_t c = 0; c < layout.size(); ++c)
        {
            const std::uint32_t count = layout.clusters()[c].indexCount / 3;
            const core::ObjectId id = _out.scene.addObject(bounds[c], count, flags, drawable.getName());
            core::SceneObject& object = _out.scene.objects[id];
            object.group = firstId;
            object.firstTriangle = _options.keepTriangles ? firstTriangle : 0;
            firstTriangle += _options.keepTriangles ? count : 0;
            ObjectRef clusterRef = ref;
            clusterRef.clusters = &layout;
            clusterRef.cluster = std::uint32_t(c);
            _out.refs.push_back(std::move(clusterRef));
            _out.indexObject(id);
        }
        return true;
    }

    core::ConvexPolygon toWorldPolygon(const std::vector<osg::Vec3d>& local, const osg::Matrixd& world) const
    {
        std::vector<core::Vec3> vertices;
        vertices.reserve(local.size());
        for (const osg::Vec3d& v : local)
            vertices.push_back(toCore(v * world));
        return core::ConvexPolygon(std::move(vertices));
    }

    void addOccluderPolygons(const Occluder& occluder)
    {
        const osg::Matrixd world = localToRoot();
        for (const Occluder::Polygon& polygon : occluder.getPolygons())
            _out.scene.occluders.push_back({toWorldPolygon(polygon, world), core::InvalidObject});
        if (!occluder.getPolygons().empty())
            noteOccluderMasks();
    }

    void addCell(const Cell& cell)
    {
        const osg::Matrixd world = localToRoot();
        core::Cell out;
        out.id = static_cast<std::uint32_t>(_out.scene.cells.size());
        out.name = cell.getName();
        const osg::BoundingBoxd& box = cell.getBounds();
        if (box.valid())
            for (unsigned i = 0; i < 8; ++i)
                out.bounds.expand(toCore(box.corner(i) * world));
        _cellIndex.emplace(out.name, out.id);
        _out.scene.cells.push_back(std::move(out));
    }

    // Portals may name cells that come later in the traversal, so they are resolved at the end.
    void resolvePortals()
    {
        for (const auto& [portal, world] : _portals)
        {
            const auto a = _cellIndex.find(portal->getCellA());
            const auto b = _cellIndex.find(portal->getCellB());
            if (a == _cellIndex.end() || b == _cellIndex.end())
            {
                OSG_WARN << "osgVis: portal '" << portal->getName() << "' joins unknown cells '" << portal->getCellA()
                         << "' and '" << portal->getCellB() << "'; ignored" << std::endl;
                continue;
            }
            _out.scene.portals.push_back({toWorldPolygon(portal->getPolygon(), world), a->second, b->second});
        }
    }

    ExtractedScene& _out;
    const ExtractionOptions& _options;
    const osg::Node* _root = nullptr;
    unsigned _unpredictableDepth = 0;
    unsigned _occluderDepth = 0;
    bool _closed = false;
    std::unordered_map<std::string, std::uint32_t> _cellIndex;
    std::unordered_map<const osg::Drawable*, osg::ref_ptr<ClusterLayout>> _layouts;
    std::vector<std::pair<osg::ref_ptr<const Portal>, osg::Matrixd>> _portals;
};
} // namespace

std::uint32_t defaultClusterThreshold()
{
    constexpr std::uint32_t Measured = 4096; // docs/clusters.md: how it was chosen
    const char* setting = std::getenv("OSGVIS_CLUSTER_THRESHOLD");
    if (!setting || !*setting)
        return Measured;
    char* end = nullptr;
    const unsigned long value = std::strtoul(setting, &end, 10);
    if (*end != '\0' || value > 0xffffffffu || setting[0] == '-')
    {
        OSG_WARN << "osgVis: OSGVIS_CLUSTER_THRESHOLD='" << setting << "' is no triangle count; using " << Measured
                 << std::endl;
        return Measured;
    }
    return std::uint32_t(value);
}

const char* whyNotAutomaticOccluder(const osg::NodePath& path)
{
    return occluderEligibility(path).notOccluderBecause;
}

void extractBelow(ExtractedScene& out, const osg::NodePath& prefix, osg::Node& child, const ExtractionOptions& options)
{
    Extractor(out, options).runBelow(prefix, child);
}

osg::ref_ptr<ExtractedScene> extractSceneQuietly(osg::Node& root, const ExtractionOptions& options)
{
    osg::ref_ptr<ExtractedScene> out = new ExtractedScene;
    Extractor(*out, options).run(root);
    assignTileKeys(*out);
    out->cullTree = buildCullTree(*out, root);
    return out;
}

void warnOversizedTiles(const ExtractedScene& scene, const ExtractedScene* previous)
{
    for (const std::string& tile : scene.oversizedTiles)
        if (!previous || std::find(previous->oversizedTiles.begin(), previous->oversizedTiles.end(), tile) ==
                             previous->oversizedTiles.end())
            OSG_WARN << "osgVis: tile " << tile
                     << " reaches outside the bound its paged node states; that node is always traversed" << std::endl;
}

osg::ref_ptr<ExtractedScene> extractScene(osg::Node& root, const ExtractionOptions& options)
{
    osg::ref_ptr<ExtractedScene> out = extractSceneQuietly(root, options);
    warnOversizedTiles(*out, nullptr);
    return out;
}
} // namespace osgVis
