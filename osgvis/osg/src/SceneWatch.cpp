// SPDX-License-Identifier: MIT
#include "SceneWatch.h"

#include "CullingContext.h"
#include "Extraction.h"
#include "OccluderEligibility.h"
#include "PagedNodeCulling.h"
#include "ValueHash.h"

#include <osgVis/Cell>
#include <osgVis/Occluder>
#include <osgVis/Portal>
#include <osgVis/VisibilityGroup>

#include <osg/AutoTransform>
#include <osg/Geode>
#include <osg/Geometry>
#include <osg/MatrixTransform>
#include <osg/PagedLOD>
#include <osg/PositionAttitudeTransform>
#include <osg/ProxyNode>

#include <algorithm>
#include <cstring>
#include <typeinfo>
#include <unordered_set>

namespace osgVis
{
namespace
{
// The cull callback the application set: osgVis's own callbacks wrap it.
const osg::Callback* applicationCullCallback(const osg::Node& node)
{
    const osg::Callback* callback = node.getCullCallback();
    if (const auto* own = dynamic_cast<const VisibilityCullCallback*>(callback))
        return own->getChained();
    if (dynamic_cast<const PagedNodeCullCallback*>(callback))
        return callback->getNestedCallback();
    return callback;
}

bool pagedNode(const osg::Node& node)
{
    return dynamic_cast<const osg::PagedLOD*>(&node) || dynamic_cast<const osg::ProxyNode*>(&node);
}

// Types whose traversal enters every child whose mask is valid: their children list says it all.
bool entersEveryChild(const osg::Node& node)
{
    return plainNodeType(node) || typeid(node) == typeid(VisibilityGroup);
}

// Placed at cull time (absolute frame, screen-aligned): the extraction keeps their objects visible
// whatever the matrix reads, which may change every frame.
bool placedAtCull(const osg::Transform& transform)
{
    return transform.getReferenceFrame() != osg::Transform::RELATIVE_RF ||
           dynamic_cast<const osg::AutoTransform*>(&transform) != nullptr;
}

osg::Matrixd localMatrix(const osg::Transform& transform)
{
    if (typeid(transform) == typeid(osg::MatrixTransform))
        return static_cast<const osg::MatrixTransform&>(transform).getMatrix();
    osg::Matrixd matrix;
    transform.computeLocalToWorldMatrix(matrix, nullptr);
    return matrix;
}

bool sameMatrix(const osg::Matrixd& a, const osg::Matrixd& b)
{
    const double* x = a.ptr();
    const double* y = b.ptr();
    bool same = true;
    for (int i = 0; i < 16; ++i)
        same &= x[i] == y[i];
    return same;
}

bool anyDrawArrays(const osg::Geometry* geometry)
{
    if (geometry)
        for (const osg::ref_ptr<osg::PrimitiveSet>& set : geometry->getPrimitiveSetList())
            if (set->getType() == osg::PrimitiveSet::DrawArraysPrimitiveType)
                return true;
    return false;
}

// note: OSG sends a changed array or index list to the GPU only after its dirty(), which counts up
// its modified count, so the counts stand for the contents; a primitive set's mode and DrawArrays'
// first and count are read at each draw, so they are compared themselves.
std::uint64_t geometryKey(const osg::Drawable& drawable, const osg::Geometry* geometry, bool drawArrays)
{
    ValueHash hash;
    hash.mix(drawable.getDrawCallback());
    hash.mix(drawable.getComputeBoundingBoxCallback());
    if (!geometry)
        return hash.value;
    const osg::Array* vertices = geometry->getVertexArray();
    hash.mix(vertices);
    hash.mix(std::uint64_t(vertices ? vertices->getModifiedCount() : 0u));
    const osg::Geometry::PrimitiveSetList& sets = geometry->getPrimitiveSetList();
    hash.mix(std::uint64_t(sets.size()));
    for (const osg::ref_ptr<osg::PrimitiveSet>& set : sets)
    {
        hash.mix(set.get());
        hash.mix((std::uint64_t(set->getModifiedCount()) << 32) | set->getMode());
        if (drawArrays && set->getType() == osg::PrimitiveSet::DrawArraysPrimitiveType)
        {
            const auto& arrays = static_cast<const osg::DrawArrays&>(*set);
            hash.mix((std::uint64_t(std::uint32_t(arrays.getFirst())) << 32) | std::uint32_t(arrays.getCount()));
        }
    }
    return hash.value;
}

std::uint64_t markerKey(const osg::Node& node)
{
    ValueHash hash;
    if (const auto* occluder = dynamic_cast<const Occluder*>(&node))
        for (const Occluder::Polygon& polygon : occluder->getPolygons())
            hash.mix(polygon);
    else if (const auto* cell = dynamic_cast<const Cell*>(&node))
    {
        hash.mix(cell->getName());
        for (int corner = 0; corner < 8; ++corner)
            for (int i = 0; i < 3; ++i)
                hash.mixDouble(cell->getBounds().corner(corner)[i]);
    }
    else if (const auto* portal = dynamic_cast<const Portal*>(&node))
    {
        hash.mix(portal->getPolygon());
        hash.mix(portal->getCellA());
        hash.mix(portal->getCellB());
    }
    return hash.value;
}

bool marker(const osg::Node& node)
{
    return dynamic_cast<const Occluder*>(&node) || dynamic_cast<const Cell*>(&node) ||
           dynamic_cast<const Portal*>(&node);
}

// Lists the children an active traversal of one group enters, without going deeper.
class SelectionProbe : public osg::NodeVisitor
{
public:
    SelectionProbe() : osg::NodeVisitor(TRAVERSE_ACTIVE_CHILDREN) {}
    std::vector<const osg::Node*>* out = nullptr;
    void apply(osg::Node& node) override { out->push_back(&node); }
};

void probe(osg::Group& group, std::vector<const osg::Node*>& out)
{
    thread_local osg::ref_ptr<SelectionProbe> probe = new SelectionProbe;
    probe->out = &out;
    group.traverse(*probe);
}
} // namespace

class SceneWatchRecorder : public osg::NodeVisitor
{
public:
    explicit SceneWatchRecorder(SceneWatch& watch) : osg::NodeVisitor(TRAVERSE_ACTIVE_CHILDREN), _watch(watch) {}

    void apply(osg::Node& node) override
    {
        record(node);
        traverse(node);
    }

private:
    void record(osg::Node& node)
    {
        hold(&node);
        SceneWatch::NodeEntry entry{&node,
                                    node.getStateSet(),
                                    node.getStateSet() ? drawnStateKey(*node.getStateSet()) : SceneWatch::NoState,
                                    applicationCullCallback(node),
                                    node.getCullCallback(),
                                    SceneWatch::None,
                                    node.getCullingActive(),
                                    false,
                                    static_cast<std::uint32_t>(_watch._children.size()),
                                    0,
                                    SceneWatch::None,
                                    SceneWatch::None};
        hold(entry.stateSet);
        hold(entry.seenCallback);
        osg::Group* group = node.asGroup();
        if (group && !pagedNode(node))
        {
            for (unsigned i = 0; i < group->getNumChildren(); ++i)
            {
                osg::Node* child = group->getChild(i);
                hold(child);
                _watch._children.push_back({child, child->getNodeMask()});
            }
            entry.listsChildren = true;
            entry.childCount = group->getNumChildren();
            if (!entersEveryChild(node))
                recordSelection(*group);
        }
        if (entry.stateSet && _states.insert(entry.stateSet).second)
            _watch._states.push_back({entry.stateSet, drawnStateKey(*entry.stateSet)});
        if (const osg::Transform* transform = node.asTransform(); transform && !placedAtCull(*transform))
        {
            entry.transform = static_cast<std::uint32_t>(_watch._transforms.size());
            _watch._transforms.push_back({localMatrix(*transform)});
        }
        if (const osg::Drawable* drawable = node.asDrawable())
        {
            entry.drawable = static_cast<std::uint32_t>(_watch._drawables.size());
            recordDrawable(*drawable);
        }
        _watch._nodes.push_back(entry);
        if (marker(node))
            _watch._markers.push_back({&node, markerKey(node)});
    }

    void recordSelection(osg::Group& group)
    {
        const auto first = static_cast<std::uint32_t>(_watch._selected.size());
        probe(group, _watch._selected);
        _watch._selections.push_back({&group, first, static_cast<std::uint32_t>(_watch._selected.size()) - first});
    }

    void recordDrawable(const osg::Drawable& drawable)
    {
        if (const osg::Geometry* geometry = drawable.asGeometry())
        {
            hold(geometry->getVertexArray());
            for (unsigned i = 0; i < geometry->getNumPrimitiveSets(); ++i)
                hold(geometry->getPrimitiveSet(i));
        }
        hold(drawable.getDrawCallback());
        hold(drawable.getComputeBoundingBoxCallback());
        const osg::Geometry* geometry = drawable.asGeometry();
        const bool drawArrays = anyDrawArrays(geometry);
        _watch._drawables.push_back(
            {drawable.getBoundingBox(), geometry, drawArrays, geometryKey(drawable, geometry, drawArrays)});
    }

    void hold(const osg::Referenced* object)
    {
        if (object)
            _watch._held.emplace_back(object);
    }

    SceneWatch& _watch;
    std::unordered_set<const osg::StateSet*> _states;
};

void SceneWatch::clear()
{
    _nodes.clear();
    _children.clear();
    _selections.clear();
    _selected.clear();
    _transforms.clear();
    _drawables.clear();
    _states.clear();
    _markers.clear();
    _held.clear();
    _adopted.clear();
}

void SceneWatch::record(osg::Node& root)
{
    clear();
    SceneWatchRecorder recorder(*this);
    root.accept(recorder);
}

// The node's slot for what it takes on after the recording, made at its first swap.
SceneWatch::AdoptedEntry& SceneWatch::adopted(const NodeEntry& entry) const
{
    if (entry.adopted == None)
    {
        entry.adopted = static_cast<std::uint32_t>(_adopted.size());
        _adopted.push_back({nullptr, NoState, nullptr});
    }
    return _adopted[entry.adopted];
}

// One node's own fields, its children, its geometry and its matrix, read in one visit.
SceneWatch::Reading SceneWatch::read(const NodeEntry& entry) const
{
    const osg::Node& node = *entry.node;
    if (const osg::StateSet* stateSet = node.getStateSet(); stateSet != entry.stateSet)
    {
        // note: OSG's pager shares equal state sets between tiles (osgDB::SharedStateManager): a state
        // set that reads the same for the extraction is no change; its values are watched from now on
        const std::uint64_t key = stateSet ? drawnStateKey(*stateSet) : NoState;
        if (key != entry.stateKey)
            return Reading::Other;
        entry.stateSet = stateSet;
        AdoptedEntry& slot = adopted(entry);
        slot.stateSet = stateSet; // held: its address is compared from now on
        slot.key = key;
    }
    if (const osg::Callback* callback = node.getCullCallback(); callback != entry.seenCallback)
    {
        if (applicationCullCallback(node) != entry.cullCallback)
            return Reading::Other;
        entry.seenCallback = callback;
        adopted(entry).callback = callback; // held: its address is compared from now on
    }
    if (node.getCullingActive() != entry.cullingActive)
        return Reading::Other;
    if (entry.listsChildren)
    {
        const osg::Group& group = *node.asGroup();
        if (group.getNumChildren() != entry.childCount)
            return Reading::Other;
        const ChildEntry* recorded = _children.data() + entry.firstChild;
        for (unsigned i = 0; i < entry.childCount; ++i)
        {
            const osg::Node* child = group.getChild(i);
            if (child != recorded[i].child || child->getNodeMask() != recorded[i].mask)
                return Reading::Other;
        }
    }
    if (entry.drawable != None)
    {
        const DrawableEntry& recorded = _drawables[entry.drawable];
        const osg::BoundingBox& box = node.asDrawable()->getBoundingBox();
        if (box._min != recorded.box._min || box._max != recorded.box._max ||
            geometryKey(*node.asDrawable(), recorded.geometry, recorded.drawArrays) != recorded.geometryKey)
            return Reading::Other;
    }
    if (entry.transform != None && !sameMatrix(localMatrix(*node.asTransform()), _transforms[entry.transform].matrix))
        return Reading::Moved;
    return Reading::Same;
}

// A state set in use edited in place: the recorded ones, and those nodes swapped to since.
bool SceneWatch::statesChanged() const
{
    for (const KeyEntry& entry : _states)
        if (drawnStateKey(*static_cast<const osg::StateSet*>(entry.object)) != entry.key)
            return true;
    for (const AdoptedEntry& entry : _adopted)
        if (entry.stateSet && drawnStateKey(*entry.stateSet) != entry.key)
            return true;
    return false;
}

bool SceneWatch::changed() const
{
    return compare().any();
}

void SceneWatch::acceptMatrices(const Difference& difference)
{
    for (std::uint32_t index : difference.movedEntries)
    {
        const NodeEntry& entry = _nodes[index];
        _transforms[entry.transform].matrix = localMatrix(*entry.node->asTransform());
    }
}

const SceneWatch::Difference& SceneWatch::compare() const
{
    Difference& out = _difference;
    out.other = false;
    out.moved.clear();
    out.movedEntries.clear();
    // note: the nodes lie scattered in memory; fetching a few entries ahead overlaps the misses
    constexpr std::size_t Ahead = 8;
    for (std::size_t i = 0; i < _nodes.size(); ++i)
    {
        if (i + Ahead < _nodes.size())
        {
            const char* ahead = reinterpret_cast<const char*>(_nodes[i + Ahead].node);
            __builtin_prefetch(ahead);
            __builtin_prefetch(ahead + 64);
            __builtin_prefetch(ahead + 128);
        }
        switch (read(_nodes[i]))
        {
        case Reading::Same:
            break;
        case Reading::Moved:
            out.moved.push_back(_nodes[i].node);
            out.movedEntries.push_back(static_cast<std::uint32_t>(i));
            break;
        case Reading::Other:
            out.other = true;
            return out;
        }
    }
    if (statesChanged())
    {
        out.other = true;
        return out;
    }
    for (const KeyEntry& entry : _markers)
        if (markerKey(*static_cast<const osg::Node*>(entry.object)) != entry.key)
        {
            out.other = true;
            return out;
        }
    thread_local std::vector<const osg::Node*> selected;
    for (const SelectionEntry& entry : _selections)
    {
        selected.clear();
        probe(*entry.group, selected);
        if (selected.size() != entry.count ||
            !std::equal(selected.begin(), selected.end(), _selected.begin() + entry.first))
        {
            out.other = true;
            return out;
        }
    }
    return out;
}
} // namespace osgVis
